// Error against the ray-traced reference (Embree: exact visibility of the emitter disk from the
// very G-buffer pixels the GPU rendered, 256 light samples), spot-lit scenes (see
// pmchss_settings.h for why spot).
#include <gtest/gtest.h>

#include <cstdio>

#include "metrics/mask_metrics.h"
#include "pmchss_fixture.h"
#include "pmchss_settings.h"
#include "raytraced_reference.h"

using namespace penumbra;

namespace {

struct Frame {
  metrics::MaskImage reference;
  metrics::CoverageMask coverage;
};

Frame trace_reference(test::PmchssRig& rig, const scene::Scene& scene) {
  rig.render();
  std::vector<glm::vec3> positions, normals;
  Frame f;
  rig.gbuffer(positions, normals, f.coverage);
  auto rs = reference::RayScene::build(scene);
  EXPECT_TRUE(rs);
  f.reference = reference::trace_visibility(*rs, rig.session().light(), positions, normals, test::kWidth,
                                            test::kHeight, {.samples = 256}, f.coverage);
  return f;
}

double rmse_of(test::PmchssRig& rig, const Frame& f, const std::vector<std::string>& settings) {
  rig.set(settings);
  rig.render();
  auto e = metrics::compare_masks(rig.shadow_mask(), f.reference, f.coverage);
  EXPECT_TRUE(e);
  return e ? e->rmse : 1.0;
}

struct ReferenceFrame {
  test::PmchssRig rig{test::kWidth, test::kHeight, test::kShadowSize};
  scene::Scene scene;
  Frame frame;
  explicit ReferenceFrame(const std::string& name) : scene(test::make_scene(name)) {
    rig.set_scene(scene);
    rig.set(test::test_settings());
    frame = trace_reference(rig, scene);
  }
};

}  // namespace

// Measured (llvmpipe, 224x168, 1024^2): physical mapping on the spot-lit ball, RMSE 0.011
// (regular), 0.015 (penumbra mask), 0.029 (min filter); a fixed full-size kernel (no contact
// hardening) 0.128. (Before the receiver plane took the fractional-texel term and the physical
// search its PCSS-like radius: 0.053, 0.053, 0.058.) Bound 0.04: the worst measured value + ~35%
// for noise-pattern and rasterisation differences between drivers. What remains is the PCSS model's own error (one averaged blocker
// depth, filtering one shadow map instead of integrating the light), not an implementation
// slack: the bound is also required to stay under half the no-contact-hardening error.
TEST(PmchssReference, PhysicalMappingIsCloseToRaytraced) {
  ReferenceFrame s("ball");
  double fixed = rmse_of(s.rig, s.frame, {"variant=regular", "penumbra_mapping=fixed"});
  std::printf("[ measure  ] ball, fixed kernel: RMSE %.4f\n", fixed);
  constexpr double kBound = 0.04;
  EXPECT_LT(kBound, 0.5 * fixed);
  for (const char* variant : {"regular", "penumbra_mask", "min_filter"}) {
    double e = rmse_of(s.rig, s.frame, {std::string("variant=") + variant, "penumbra_mapping=physical"});
    std::printf("[ measure  ] ball, %s, physical: RMSE %.4f\n", variant, e);
    EXPECT_LT(e, kBound) << variant;
  }
  test::save_for_inspection("reference_ball", s.frame.reference);
}

// Calibration of k (Listing 4's 80 is tuned for Sponza with its own depth units and kernel
// size; the mapping saturate(k p^2) x shadow_filter_max_size must be re-fitted per scale): on the
// poles scene, regular CHSS, k on a sqrt(2) grid from 0.25 to 64. Measured: minimum at k = 1.4
// (RMSE ~0.036), k = 80 gives ~0.138. The minimum must be interior (a real minimum, not the grid
// edge) and equal to the kCalibratedK the other tests use.
TEST(PmchssReference, CalibratedKIsTheGridMinimum) {
  ReferenceFrame s("poles");
  s.rig.set({"variant=regular", "penumbra_mapping=paper"});
  double best_k = 0.0, best = 1e9, at_80 = rmse_of(s.rig, s.frame, {"k=80"});
  std::vector<double> grid;
  for (double k = 0.25; k <= 64.0 * 1.01; k *= 1.41421356) grid.push_back(k);
  for (double k : grid) {
    double e = rmse_of(s.rig, s.frame, {"k=" + std::to_string(k)});
    std::printf("[ measure  ] poles, k = %.2f: RMSE %.4f\n", k, e);
    if (e < best) best = e, best_k = k;
  }
  std::printf("[ measure  ] poles: best k = %.2f (RMSE %.4f), k = 80: RMSE %.4f\n", best_k, best, at_80);
  EXPECT_GT(best_k, grid.front());
  EXPECT_LT(best_k, grid.back());
  EXPECT_NEAR(best_k, test::kCalibratedK, 0.05 * test::kCalibratedK);
  EXPECT_LT(best, 0.75 * at_80);
}

// The calibrated k carries over to another scene (the ball), for the two average-blocker
// variants. Measured: 0.026 (regular), 0.019 (penumbra mask). Bound 0.035: measured + ~35%
// (the k was fitted on another scene). Not for min_filter: its minimum depth overestimates p,
// so a k fitted to the average blocker over-blurs (measured 0.097; section 2.3 describes it).
TEST(PmchssReference, CalibratedKHoldsOnTheBall) {
  ReferenceFrame s("ball");
  for (const char* variant : {"regular", "penumbra_mask"}) {
    double e = rmse_of(s.rig, s.frame, {std::string("variant=") + variant, "penumbra_mapping=paper",
                                        "k=" + std::to_string(test::kCalibratedK)});
    std::printf("[ measure  ] ball, %s, k = %.2f: RMSE %.4f\n", variant, test::kCalibratedK, e);
    EXPECT_LT(e, 0.035) << variant;
  }
}
