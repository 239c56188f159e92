// The mpg graph (techniques/mpg/mpg.json) through the compiler: `repeat` makes max_passes blur
// passes, `enabled` keeps exactly one alteration and the optional passes, structural parameters
// recompile and the others do not; the pass types accept every value the technique's ranges
// allow (the check the reworked graph compiler will make); `penumbra graph --frame` prints the
// expected pass count.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "mpg_rig.h"
#include "mpg_settings.h"
#include "technique/technique.h"
#include "test_support/run_command.h"
#include "techniques/builtin_techniques.h"

using namespace penumbra;

namespace {

size_t count_passes(const graph::CompiledPlan& plan, const std::string& declared_as) {
  return static_cast<size_t>(std::count_if(plan.passes.begin(), plan.passes.end(),
                                           [&](const graph::PlannedPass& p) { return p.declared_as == declared_as; }));
}

bool has_pass(const graph::CompiledPlan& plan, const std::string& name) {
  return std::any_of(plan.passes.begin(), plan.passes.end(), [&](const graph::PlannedPass& p) { return p.name == name; });
}

using penumbra::test::CommandRun;
CommandRun run_cli(const std::string& args) {
  return penumbra::test::run_command(std::string(PENUMBRA_CLI) + " " + args);
}

}  // namespace

TEST(MpgGraph, RepeatAndEnabledShapeThePlan) {
  test::MpgRig rig(64, 48, 256);
  rig.set_scene(test::make_scene("ball"));
  technique::TechniqueSession& s = rig.session();
  // Defaults: multi-pass with 10 blur passes, named multipass_blur[0..9]; dilation on; no
  // early-out; the other alterations disabled, not merely culled.
  EXPECT_EQ(count_passes(s.plan(), "multipass_blur"), 10u);
  EXPECT_TRUE(has_pass(s.plan(), "multipass_blur[0]") && has_pass(s.plan(), "multipass_blur[9]"));
  EXPECT_TRUE(has_pass(s.plan(), "dilate_x") && has_pass(s.plan(), "dilate_y"));
  for (const char* absent : {"pcf_filter", "gaussian_filter_x", "gaussian_filter_y", "umbra_early_out_x"}) {
    EXPECT_FALSE(has_pass(s.plan(), absent)) << absent;
    EXPECT_NE(std::find(s.plan().disabled.begin(), s.plan().disabled.end(), absent), s.plan().disabled.end()) << absent;
  }
  rig.render();

  // max_passes is structural: a new plan with that many repetitions.
  const int compiles = s.compile_count();
  rig.set({"max_passes=4"});
  EXPECT_EQ(s.compile_count(), compiles + 1);
  EXPECT_EQ(count_passes(s.plan(), "multipass_blur"), 4u);
  rig.render();
  rig.set({"max_passes=1"});  // a single repetition keeps the declared name
  EXPECT_EQ(count_passes(s.plan(), "multipass_blur"), 1u);
  EXPECT_TRUE(has_pass(s.plan(), "multipass_blur"));
  // A uniform does not recompile.
  const int before_uniform = s.compile_count();
  rig.set({"poisson_taps=8", "max_kernel=29", "mapping=paper", "depth_tolerance=0.2"});
  EXPECT_EQ(s.compile_count(), before_uniform);
  rig.render();

  // The alteration is structural: exactly its pass 4 remains.
  rig.set({"alteration=pcf"});
  EXPECT_EQ(count_passes(s.plan(), "pcf_filter"), 1u);
  EXPECT_EQ(count_passes(s.plan(), "multipass_blur"), 0u);
  rig.render();
  rig.set({"alteration=gaussian"});
  EXPECT_TRUE(has_pass(s.plan(), "gaussian_filter_x") && has_pass(s.plan(), "gaussian_filter_y"));
  EXPECT_FALSE(has_pass(s.plan(), "pcf_filter"));
  rig.render();

  // The optional passes.
  rig.set({"umbra_early_out=true", "dilation=false", "debug_outputs=false"});
  EXPECT_TRUE(has_pass(s.plan(), "umbra_early_out_x") && has_pass(s.plan(), "umbra_early_out_y"));
  EXPECT_FALSE(has_pass(s.plan(), "dilate_x"));
  EXPECT_FALSE(has_pass(s.plan(), "debug_distance_view") || has_pass(s.plan(), "debug_penumbra_view"));
  rig.render();
}

// The plan as `penumbra graph --frame` prints it: G-buffer, shadow map, distance map, dilation
// (x, y), the D view, pass 4, resolve, the Figure 4 view, lighting = 9 passes + pass 4's; without
// the dilation (whose y pass writes it) the multi-pass blur's tile list is a pass of its own.
TEST(MpgGraph, CliFramePlanHasTheExpectedPassCount) {
  const std::string graph = std::string(PENUMBRA_SOURCE_DIR) + "/techniques/mpg/mpg.json --frame";
  struct Case {
    std::string sets;
    int passes;
  };
  for (const Case& c : {Case{"", 9 + 10}, Case{"--set max_passes=7", 9 + 7}, Case{"--set max_passes=32", 9 + 32},
                        Case{"--set tiles=false", 9 + 10}, Case{"--set alteration=pcf", 9 + 1},
                        Case{"--set alteration=gaussian", 9 + 2},
                        Case{"--set umbra_early_out=true --set dilation=false", 10 + 10},
                        Case{"--set dilation=false", 8 + 10}}) {
    CommandRun r = run_cli("graph " + graph + " " + c.sets);
    ASSERT_EQ(r.exit_code, 0) << c.sets << "\n" << r.output;
    EXPECT_NE(r.output.find(", " + std::to_string(c.passes) + " passes"), std::string::npos) << c.sets << "\n" << r.output;
  }
  CommandRun bad = run_cli("graph " + graph + " --set max_passes=33");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("[1, 32]"), std::string::npos) << bad.output;
}
