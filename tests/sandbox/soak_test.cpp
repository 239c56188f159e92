// 2,000 random scripted steps (technique swaps, parameter changes, resizes, compare toggles,
// resets; seeded) through the same controller and script runner as the window, headless under
// OSMesa: no GL error, no failed step, and the texture pools stay bounded.
#include <gtest/gtest.h>

#include <algorithm>

#include "sandbox/controller.h"
#include "sandbox/script.h"
#include "sandbox/script_runner.h"
#include "test_support/gl_context.h"
#include "techniques/builtin_techniques.h"
#include "tiny_technique.h"

namespace penumbra::sandbox {
namespace {

// Comfortably above any one plan's needs (a G-buffer, a few masks, two generations kept by
// the pool), far below what a leak over 2,000 steps would reach.
constexpr size_t kPoolBound = 64;

TEST(SandboxSoak, TwoThousandRandomStepsKeepTheSandboxHealthy) {
  test::gl_context();
  technique::TechniqueRegistry registry;
  register_builtin_techniques(registry);
  sandbox_test::register_tiny_technique(registry);
  exec::PassLibrary library = make_pass_library(registry);

  std::vector<TechniqueInfo> infos;
  for (const technique::Technique& t : registry.all()) {
    // The reference's sample counts and map sizes reach 65536 and 16384 texels: thousands of
    // random frames of it take many minutes on llvmpipe. It has its own tests; the Xvfb test
    // visits its parameters' min/max/default once.
    if (t.name == "reference") continue;
    auto g = technique::load_technique_graph(t, library.declarations());
    ASSERT_TRUE(g) << g.error().to_string();
    infos.push_back({t.name, g->parameters});
  }
  auto steps = parse_script(soak_script(infos, /*seed=*/20240917, 2000, /*max_size=*/64), "soak");
  ASSERT_TRUE(steps) << steps.error().to_string();
  ASSERT_EQ(steps->size(), 2000u);

  SandboxController controller(registry, library);
  ASSERT_TRUE(controller.session().set_shadow_size(512));
  ASSERT_TRUE(controller.init("showcase", sandbox_test::kTinyTechnique, 48, 32));
  controller.compare().stats_every = 7;  // exercise the read-back path too
  ScriptRunner runner(std::move(*steps), [&](int w, int h) { return controller.resize(w, h); });

  size_t max_primary = 0, max_secondary = 0;
  int frames = 0, refused_frames = 0;
  std::string first_refusal;
  while (!runner.done()) {
    Status step = runner.before_frame(controller);
    ASSERT_TRUE(step) << step.error().to_string();
    if (runner.done()) break;
    // A random combination may be refused by a pass as bad input (e.g. a filter radius below one
    // texel of a small shadow map): the sandbox shows that message and keeps running, so the
    // soak does too. Internal errors fail it.
    if (Status s = controller.render_frame(); !s) {
      ASSERT_NE(s.error().kind, ErrorKind::internal) << s.error().to_string();
      if (first_refusal.empty()) first_refusal = s.error().to_string();
      ++refused_frames;
    }
    ++frames;
    max_primary = std::max(max_primary, controller.session().pool().texture_count());
    if (controller.secondary())
      max_secondary = std::max(max_secondary, controller.secondary()->pool().texture_count());
    ASSERT_LT(max_primary, kPoolBound);
    ASSERT_LT(max_secondary, kPoolBound);
    Status gl = SandboxController::check_gl_errors("after frame " + std::to_string(frames));
    ASSERT_TRUE(gl) << gl.error().to_string();
  }
  EXPECT_GT(frames, 300);
  EXPECT_LT(refused_frames, frames / 4) << first_refusal;
  std::printf("soak: %d frames (%d refused as bad input), pool peak %zu (primary) %zu (secondary), %zu "
              "techniques\n%s\n", frames, refused_frames, max_primary, max_secondary, infos.size(),
              first_refusal.c_str());
}

}  // namespace
}  // namespace penumbra::sandbox
