// Progressive raster accumulation: it converges towards the ray-traced reference as samples
// come in, and the reset rule restarts it when the light moves.
#include <gtest/gtest.h>

#include <optional>

#include "exec/gpu_scene.h"
#include "metrics/mask_metrics.h"
#include "reference_session.h"
#include "techniques/reference/reference_frame_key.h"
#include "test_support/gl_context.h"
#include "test_support/technique_rig.h"

using namespace penumbra;

namespace {
// The reference pass's progress: it reports some once it has run.
exec::PassProgress progress(test::ReferenceSession& r) {
  const std::optional<exec::PassProgress>& p = r.session().progress();
  EXPECT_TRUE(p.has_value()) << "the reference reported no progress";
  return p.value_or(exec::PassProgress{});
}
}  // namespace

TEST(ReferenceProgressive, ErrorToRaytracedFallsAsSamplesAccumulate) {
  test::ReferenceSession r("ball");
  r.set("method=raytraced");
  r.set("rays=256");
  r.render();
  const metrics::MaskImage truth = r.mask();
  const metrics::CoverageMask coverage = r.coverage();
  r.set("method=raster");
  r.set("samples=256");
  r.set("map_size=1024");
  r.set("maps_per_frame=4");
  std::vector<double> rmse;
  int done = 0;
  for (int target : {4, 16, 64, 256}) {
    while (done < target) {
      r.render();
      done += 4;
    }
    ASSERT_EQ(progress(r).done, target);
    auto e = metrics::compare_masks(r.mask(), truth, coverage);
    ASSERT_TRUE(e);
    rmse.push_back(e->rmse);
  }
  for (size_t i = 1; i < rmse.size(); ++i)
    EXPECT_LT(rmse[i], rmse[i - 1]) << "RMSE after step " << i << ": " << rmse[i] << " vs " << rmse[i - 1];
  EXPECT_LT(rmse.back(), 0.01);
}

TEST(ReferenceProgressive, MovingTheLightResetsTheCount) {
  test::ReferenceSession r("ball");
  r.set("samples=64");
  r.set("map_size=256");
  r.set("maps_per_frame=8");
  r.render(3);
  exec::PassProgress p = progress(r);
  EXPECT_EQ(p.done, 24);
  EXPECT_EQ(p.total, 64);
  const std::uint64_t restarts = p.restarts;
  r.render();  // nothing changed: keeps accumulating
  EXPECT_EQ(progress(r).done, 32);
  r.session().light().position += glm::vec3(0.3f, 0.0f, 0.0f);
  r.render();
  p = progress(r);
  EXPECT_EQ(p.done, 8) << "a moved light must restart the accumulation";
  EXPECT_EQ(p.restarts, restarts + 1);
  r.session().camera().position += glm::vec3(0.0f, 0.1f, 0.0f);
  r.render();
  EXPECT_EQ(progress(r).done, 8) << "a moved camera must restart the accumulation";
  r.render(20);  // runs to completion and stops there
  EXPECT_EQ(progress(r).done, 64);
  EXPECT_TRUE(progress(r).complete());
}

TEST(ReferenceProgressive, RaytracedTracesOnlyWhenInputsChange) {
  test::ReferenceSession r("ball", 64);
  r.set("method=raytraced");
  r.set("rays=16");
  r.render();
  const std::uint64_t restarts = progress(r).restarts;
  EXPECT_TRUE(progress(r).complete());
  r.render(2);
  EXPECT_EQ(progress(r).restarts, restarts);
  const metrics::MaskImage before = r.mask();
  // Turn the light (a directional light's position alone does not move its shadows).
  r.session().light().direction = glm::normalize(r.session().light().direction + glm::vec3(0.3f, 0.0f, 0.0f));
  r.render();
  EXPECT_EQ(progress(r).restarts, restarts + 1);
  EXPECT_NE(before.pixels, r.mask().pixels);
}

TEST(ReferenceProgressive, ProgressBelongsToTheSessionsPlan) {
  test::ReferenceSession r("ball", 64);
  r.set("samples=16");
  r.set("map_size=256");
  r.set("maps_per_frame=4");
  r.render();
  EXPECT_EQ(progress(r).done, 4);
  EXPECT_EQ(progress(r).total, 16);
  EXPECT_EQ(progress(r).unit, "shadow maps");
  ASSERT_TRUE(r.session().set_technique("hard"));
  r.render();
  EXPECT_FALSE(r.session().progress().has_value()) << "a technique without a progressive pass reports none";
}

// The reset rule names a scene by its serial: a scene made where the last one was, with the same
// triangles and bounds but another material, is another scene (keyed by address, triangle count
// and bounds, both references and the shared Embree scene took it for the old one).
TEST(ReferenceResetRule, ASceneMadeWhereTheLastOneWasIsAnotherScene) {
  test::gl_context();
  scene::Scene a = test::builtin_scene("ball");
  scene::Scene b = a;
  b.materials.front().alpha_mode = scene::AlphaMode::mask;  // the ground: same geometry, other casting
  std::optional<exec::GpuScene> gpu;
  exec::FrameInputs frame;
  gpu.emplace(a);
  frame.scene = &*gpu;
  const reference::ReferenceFrameKey key_a = reference::make_frame_key(frame, {});
  gpu.reset();
  gpu.emplace(b);
  ASSERT_EQ(frame.scene, &*gpu) << "the new scene sits where the old one did";
  const reference::ReferenceFrameKey key_b = reference::make_frame_key(frame, {});
  EXPECT_NE(key_a, key_b);
  EXPECT_EQ(key_b, reference::make_frame_key(frame, {})) << "the same scene keeps its key";
}
