// The two references must agree: same light model (scene::light_sample_points, same N = M
// points and seed; a point light's sphere: reference/sphere_light_points.h), so the remaining difference is the raster method's depth-map discretisation
// and bias. 128x128 screen, N = M = 256, 2048^2 sample maps.
#include <gtest/gtest.h>

#include <map>

#include "metrics/heat_map.h"
#include "metrics/mask_metrics.h"
#include "reference_session.h"
#include "test_support/inspection.h"

using namespace penumbra;

namespace {

struct Agreement {
  metrics::MaskErrors errors;
  metrics::MaskImage raytraced;
};

Agreement raster_vs_raytraced(const std::string& scene, const std::map<std::string, float>& params = {}) {
  test::ReferenceSession r(scene);
  if (!params.empty()) r.set_scene(test::builtin_scene(scene, params));
  r.set("method=raytraced");
  r.set("rays=256");
  r.render();
  Agreement a;
  a.raytraced = r.mask();
  const metrics::CoverageMask coverage = r.coverage();
  r.set("method=raster");
  r.set("samples=256");
  r.set("map_size=2048");  // 1024 passes too on ball (0.0017) but leaves fence at 0.009
  r.set("maps_per_frame=64");
  r.render(4);
  EXPECT_TRUE(r.session().progress().has_value()) << "the raster reference reported no progress";
  const exec::PassProgress p = r.session().progress().value_or(exec::PassProgress{});
  EXPECT_EQ(p.label, "raster");
  EXPECT_EQ(p.done, 256);
  EXPECT_TRUE(p.complete());
  const metrics::MaskImage raster = r.mask();
  // Pictures to look at when it fails.
  test::save_for_inspection(scene + "_raytraced", a.raytraced);
  test::save_for_inspection(scene + "_raster", raster);
  if (auto heat = metrics::error_heat_map(raster, a.raytraced, coverage, 0.25f))
    test::save_for_inspection(scene + "_error", *heat);
  auto e = metrics::compare_masks(raster, a.raytraced, coverage);
  EXPECT_TRUE(e);
  a.errors = *e;
  return a;
}

void expect_agreement(const std::string& scene, const std::map<std::string, float>& params = {}) {
  const Agreement a = raster_vs_raytraced(scene, params);
  // The frame is not trivial: it has receivers, shadow and a penumbra.
  EXPECT_GT(a.errors.pixels, 8000u);
  EXPECT_GT(a.errors.penumbra_pixels, 100u);
  float lo = 1.0f;
  for (float v : a.raytraced.pixels) lo = std::min(lo, v);
  EXPECT_EQ(lo, 0.0f) << "no umbra in the ray-traced reference";
  EXPECT_LT(a.errors.rmse, 0.01) << scene << ": RMSE " << a.errors.rmse << ", penumbra RMSE "
                                 << a.errors.rmse_penumbra << ", max " << a.errors.max_error;
  std::printf("[ agreement ] %s: RMSE %.5f, penumbra RMSE %.5f, MAE %.5f, max %.4f, SSIM %.4f (%zu px, %zu penumbra)\n",
              scene.c_str(), a.errors.rmse, a.errors.rmse_penumbra, a.errors.mae, a.errors.max_error,
              a.errors.ssim, a.errors.pixels, a.errors.penumbra_pixels);
}

}  // namespace

TEST(ReferenceAgreement, RasterMatchesRaytracedOnBall) { expect_agreement("ball"); }
TEST(ReferenceAgreement, RasterMatchesRaytracedOnFence) { expect_agreement("fence"); }
// A point light inside the scene: the raster reference renders six faces from every sample point,
// its points filling the lamp's ball so that each receiver sees them over its own disk
// (sphere_light_points.h), where the ray tracer draws them on that disk. A larger lamp than the
// room's default, for a penumbra of more than 100 pixels at 128x128.
TEST(ReferenceAgreement, RasterMatchesRaytracedInARoomLitFromInside) {
  expect_agreement("room", {{"light_size", 0.6f}});
}
