// Error of the baselines against the exact area-light visibility (Embree, techniques/reference)
// of the same frame: the reference traces 256 stratified light samples per pixel from the GPU
// G-buffer's positions and normals (so both see identical receivers), coverage = position.w > 0.
//
// Prints the table used in the issue notes (RMSE over receivers, RMSE over reference penumbra
// pixels, max error, SSIM, and tech_ms: the sum of the per-pass medians over 12 frames of the
// technique's own passes, shadow map included; glFinish + CPU clock on llvmpipe (indicative
// only), GPU timestamps with PENUMBRA_TEST_CONTEXT=egl on a GPU) and asserts the PCSS bounds
// below. Reproduce with
//   build/<dir>/tests/baseline/baseline_reference_tests
// (PENUMBRA_TEST_IMAGES=DIR also writes the masks and error heat maps as PNG). On the GPU machine:
//   scripts/gpu/bundle.sh build/bl_gpu build/<release>/tests/baseline/baseline_reference_tests
//   (run, carry build/bl_gpu) source build/bl_gpu/env.sh && PENUMBRA_SHADER_DIR=$PWD
//     PENUMBRA_TEST_CONTEXT=egl PENUMBRA_TEST_SIZE=1920x1080 PENUMBRA_TEST_FRAMES=60
//     build/bl_gpu/bin/baseline_reference_tests
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "baseline_frame.h"
#include "metrics/heat_map.h"
#include "metrics/mask_metrics.h"
#include "raytraced_reference.h"
#include "scene/builtin_scenes.h"
#include "test_support/inspection.h"
#include "test_support/reference_comparison.h"

namespace penumbra::test {
namespace {

int env_int(const char* name, int fallback) {
  const char* s = std::getenv(name);
  return s && std::atoi(s) > 0 ? std::atoi(s) : fallback;
}

// PENUMBRA_TEST_SIZE=WxH overrides the size for timing runs on a GPU (the bounds below were
// measured at 192x144 and are only asserted at that size).
int env_size(int index, int fallback) {
  const char* s = std::getenv("PENUMBRA_TEST_SIZE");
  int w = 0, h = 0;
  if (!s || std::sscanf(s, "%dx%d", &w, &h) != 2 || w <= 0 || h <= 0) return fallback;
  return index == 0 ? w : h;
}
const int kW = env_size(0, 192), kH = env_size(1, 144);
const bool kDefaultSize = kW == 192 && kH == 144;
// PENUMBRA_TEST_FRAMES=N: frames per technique (timing medians), default 12.
const int kFrames = env_int("PENUMBRA_TEST_FRAMES", 12);

struct Row {
  metrics::MaskErrors errors;
  double ms = 0.0;
  std::string passes;
};

// One scene: the reference once, then each technique against it.
std::map<std::string, Row> evaluate(BaselineRenderer& r, const std::string& scene_name,
                                    const std::vector<std::string>& techniques) {
  scene::Scene s = builtin_scene(scene_name);
  Result<reference::RayScene> rs = reference::RayScene::build(s);
  EXPECT_TRUE(rs);
  if (!rs) return {};
  // The G-buffer is the same for every technique; take it from the first render.
  std::map<std::string, Row> rows;
  metrics::MaskImage ref;
  for (const std::string& t : techniques) {
    RenderedFrame f = r.render(s, t, {}, kW, kH, kFrames);
    if (ref.pixels.empty())
      ref = reference::trace_visibility(*rs, s.light, f.positions, f.normals, kW, kH, {.samples = 256}, f.coverage);
    rows[t] = {frame_errors(f.mask, ref, f), f.technique_ms, f.pass_ms};
    const std::string base = scene_name + "_" + t;
    save_for_inspection(base + "_mask", f.mask);
    if (auto heat = metrics::error_heat_map(f.mask, ref, f.coverage, 0.25f))
      save_for_inspection(base + "_error", *heat);
    save_for_inspection(base + "_reference", ref);
  }
  return rows;
}

// Bounds on PCSS's RMSE over receivers, from the values measured (OSMesa llvmpipe 22.3.6,
// 192x144, shadow map 2048, 256 light samples, 16/16 taps; the soft penumbra's RMSE in brackets):
//           measured  bound   (hard, pcf on the same frames)
//   ball     0.0074   0.0096  (0.0300, 0.0238)   penumbra 0.040 (0.275, 0.209)
//   fence    0.0358   0.046   (0.0745, 0.0578)   penumbra 0.041 (0.277, 0.193)
//   poles    0.0164   0.021   (0.0530, 0.0347)   penumbra 0.035 (0.311, 0.220)
// Margins of ~30%: room for another GL driver's rasterisation and the per-pixel IGN rotation,
// while every bound is below PCF's error, so a PCSS that degenerated to fixed-width PCF or to
// hard shadows fails (and the pcss < pcf, pcss < hard checks say which).
struct Bound {
  const char* scene;
  double pcss_rmse;
};
constexpr Bound kBounds[] = {{"ball", 0.0096}, {"fence", 0.046}, {"poles", 0.021}};

TEST(BaselineReferenceError, PcssErrorIsBoundedAndBelowHardAndPcf) {
  BaselineRenderer r;
  std::printf("%-7s %-5s %8s %14s %8s %8s %10s\n", "scene", "tech", "rmse", "rmse_penumbra", "max", "ssim",
              "tech_ms");
  for (const Bound& b : kBounds) {
    SCOPED_TRACE(b.scene);
    auto rows = evaluate(r, b.scene, {"hard", "pcf", "pcss"});
    for (const char* t : {"hard", "pcf", "pcss"}) {
      const Row& row = rows[t];
      std::printf("%-7s %-5s %8.4f %14.4f %8.3f %8.4f %10.3f   (%s)\n", b.scene, t, row.errors.rmse,
                  row.errors.rmse_penumbra, row.errors.max_error, row.errors.ssim, row.ms, row.passes.c_str());
    }
    if (kDefaultSize) {
      EXPECT_LT(rows["pcss"].errors.rmse, b.pcss_rmse);
    }
    EXPECT_LT(rows["pcss"].errors.rmse, rows["hard"].errors.rmse);
    EXPECT_LT(rows["pcss"].errors.rmse, rows["pcf"].errors.rmse);
    EXPECT_LT(rows["pcss"].errors.rmse_penumbra, rows["hard"].errors.rmse_penumbra);
  }
}

}  // namespace
}  // namespace penumbra::test
