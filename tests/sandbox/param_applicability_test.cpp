// Which parameters have an effect, derived from the graph: an `applies` condition, or the
// passes of the compiled plan that read the parameter (disabled, culled, `when` not holding).
#include <gtest/gtest.h>

#include "sandbox/param_applicability.h"

namespace penumbra::sandbox {
namespace {

using graph::ParamDesc;
using graph::ParamType;

struct Fixture {
  graph::GraphDesc graph;
  graph::CompiledPlan plan;
  graph::ParameterSet params;
};

// kernel (structural enum), use_blur (structural bool), samples (applies under vogel), radius
// (read by pass "blur", enabled by $use_blur), level (read by pass "fill").
Fixture make(const std::string& kernel, bool use_blur) {
  Fixture f;
  ParamDesc k = graph::enum_param("kernel", "box", {"box", "vogel"}, "kernel");
  k.structural = true;
  ParamDesc b = graph::bool_param("use_blur", true, "blur");
  b.structural = true;
  ParamDesc samples = graph::int_param("samples", 16, 1, 64, "", "taps");
  samples.applies = "$kernel == \"vogel\"";
  ParamDesc level = graph::real_param("level", 0.5, 0.0, 1.0, "", "level");
  level.capped_by = ParamDesc::Cap{"radius", "$use_blur", "the blur spreads it"};
  f.graph.parameters = {k, b, samples, graph::real_param("radius", 2.0, 0.0, 8.0, "texels", "blur radius"), level};
  f.params = graph::ParameterSet(f.graph.parameters);
  EXPECT_TRUE(f.params.set("kernel", kernel));
  EXPECT_TRUE(f.params.set("use_blur", use_blur));
  graph::PassDecl fill{.type = "fill", .name = "fill"};
  fill.params.push_back({.name = "level", .reference = "level"});
  fill.params.push_back({.name = "samples", .reference = "samples"});
  graph::PassDecl blur{.type = "blur", .name = "blur"};
  blur.params.push_back({.name = "radius", .reference = "radius"});
  blur.enabled = "$use_blur";
  f.graph.passes = {fill, blur};
  graph::PlannedPass planned_fill{.type = "fill", .name = "fill", .declared_as = "fill"};
  planned_fill.params = {{"level", 0.5, "level"}, {"samples", 16, "samples"}};
  f.plan.passes.push_back(planned_fill);
  if (use_blur) {
    graph::PlannedPass planned_blur{.type = "blur", .name = "blur", .declared_as = "blur"};
    planned_blur.params = {{"radius", 2.0, "radius"}};
    f.plan.passes.push_back(planned_blur);
  } else {
    f.plan.disabled.push_back("blur");
  }
  return f;
}

Applicability of(const Fixture& f, const std::string& name) {
  return param_applicability(*f.params.find(name), f.params, f.graph, f.plan);
}

TEST(ParamApplicability, ACapIsNamedWithItsValueOnlyWhileItsConditionHolds) {
  const Applicability capped = of(make("box", true), "level");
  EXPECT_TRUE(capped.applies);
  EXPECT_EQ(capped.capped, "capped by radius (now 2): the blur spreads it");
  EXPECT_EQ(of(make("box", false), "level").capped, "");
  EXPECT_EQ(of(make("box", true), "radius").capped, "");
}

TEST(ParamApplicability, AnAppliesConditionThatDoesNotHoldDisablesWithItsText) {
  const Fixture box = make("box", true);
  const Applicability a = of(box, "samples");
  EXPECT_FALSE(a.applies);
  EXPECT_NE(a.reason.find("$kernel == \"vogel\""), std::string::npos) << a.reason;
  EXPECT_NE(a.reason.find("kernel is \"box\""), std::string::npos) << a.reason;
  EXPECT_TRUE(of(make("vogel", true), "samples").applies);
}

TEST(ParamApplicability, APassThatIsDisabledTakesItsParametersWithIt) {
  const Fixture off = make("box", false);
  const Applicability a = of(off, "radius");
  EXPECT_FALSE(a.applies);
  EXPECT_NE(a.reason.find("pass 'blur' is disabled (enabled: $use_blur)"), std::string::npos) << a.reason;
  EXPECT_TRUE(of(make("box", true), "radius").applies);
  EXPECT_TRUE(of(off, "level").applies) << "read by a planned pass";
  EXPECT_TRUE(of(off, "use_blur").applies) << "structural parameters shape the graph";
}

TEST(ParamApplicability, CulledPassesAndUnreadParametersAreExplained) {
  Fixture f = make("box", true);
  f.plan.passes.pop_back();
  f.plan.culled.push_back("blur");
  EXPECT_NE(of(f, "radius").reason.find("pass 'blur' is culled"), std::string::npos);
  f.graph.passes.pop_back();
  EXPECT_NE(of(f, "radius").reason.find("no pass of the compiled graph reads it"), std::string::npos);
}

TEST(ParamApplicability, OddOnlyIntegersOfferOnlyValidValues) {
  ParamDesc d = graph::int_param("box_size", 3, 1, 31, "texels", "kernel width");
  d.step = 2;
  EXPECT_EQ(valid_int_value(d, 4), 5);
  EXPECT_EQ(valid_int_value(d, 3), 3);
  EXPECT_EQ(valid_int_value(d, 0), 1);
  EXPECT_EQ(valid_int_value(d, 32), 31);
  EXPECT_EQ(valid_int_value(d, 100), 31);
  for (int v = -5; v < 50; ++v) EXPECT_EQ(valid_int_value(d, v) % 2, 1) << v;
  ParamDesc plain = graph::int_param("n", 3, 1, 10, "", "");
  EXPECT_EQ(valid_int_value(plain, 4), 4);
  EXPECT_EQ(valid_int_value(plain, 11), 10);
}

}  // namespace
}  // namespace penumbra::sandbox
