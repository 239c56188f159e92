// Error against the ray-traced reference (Embree: exact visibility of the emitter disk from the
// very G-buffer pixels the GPU rendered, 128 light samples), on the scenes' own sun-like lights.
// `hard` and `pcf` are measured on the same frame: the requirement is that mpg's penumbra
// error is clearly below theirs. 320x180 with a 2048^2 map (penumbra eval's map and aspect at half
// its size): mpg filters in screen space, so its accuracy needs penumbrae a few pixels wide; at
// 224x168 with a 1024^2 map the fence's penumbrae are 1-2 px and mpg only tied PCF there
// (0.196 vs 0.208, on the earlier penumbra measure that counted geometric edges). Penumbra RMSE
// here is the soft penumbra's, as penumbra eval reports it (test_support/reference_comparison.h).
#include <gtest/gtest.h>

#include <cstdio>

#include "metrics/mask_metrics.h"
#include "mpg_rig.h"
#include "mpg_settings.h"
#include "raytraced_reference.h"
#include "test_support/reference_comparison.h"

using namespace penumbra;

namespace {

constexpr int kWidth = 320, kHeight = 180, kShadowSize = 2048;

struct ReferenceFrame {
  test::MpgRig rig{kWidth, kHeight, kShadowSize};
  test::RenderedFrame frame;  // its G-buffer is every technique's here
  metrics::MaskImage reference;

  explicit ReferenceFrame(const std::string& name) : ReferenceFrame(test::make_scene(name)) {}
  explicit ReferenceFrame(const scene::Scene& scene) : frame(rig.render_frame(scene, "mpg")) {
    auto rs = reference::RayScene::build(scene);
    EXPECT_TRUE(rs);
    reference = reference::trace_visibility(*rs, rig.session().light(), frame.positions, frame.normals, kWidth, kHeight,
                                            {.samples = 128}, frame.coverage);
  }

  // Over the frame's pixel classes: rmse_penumbra is the soft penumbra's, as penumbra eval's.
  metrics::MaskErrors errors(const std::string& technique, const std::vector<std::string>& settings = {}) {
    Status s = rig.session().set_technique(technique);
    EXPECT_TRUE(s) << s.error().to_string();
    rig.set(settings);
    rig.render();
    return test::frame_errors(rig.shadow_mask(), reference, frame);
  }
};

}  // namespace

// Defaults (multi-pass, physical mapping) against hard shadows and PCF on the same frame.
// Measured penumbra RMSE (llvmpipe): ball mpg 0.031 / hard 0.275 / pcf 0.209; fence 0.051 /
// 0.277 / 0.195; palms 0.048 / 0.413 / 0.270: at most 0.26 x PCF (0.47 x before the footprint S
// and the turned Poisson sets). Asserted: mpg's penumbra RMSE at most 0.35 x the better of hard
// and PCF on each scene, and its overall RMSE below both.
class MpgReference : public ::testing::TestWithParam<std::string> {};

TEST_P(MpgReference, DefaultsBeatHardAndPcf) {
  ReferenceFrame f(GetParam());
  const metrics::MaskErrors mpg = f.errors("mpg");
  test::save_for_inspection("reference_" + GetParam(), f.reference);
  test::save_for_inspection("mpg_" + GetParam(), f.rig.shadow_mask());
  const metrics::MaskErrors hard = f.errors("hard");
  const metrics::MaskErrors pcf = f.errors("pcf");
  std::printf("[ measure  ] %s penumbra RMSE: mpg %.4f, hard %.4f, pcf %.4f (RMSE %.4f / %.4f / %.4f)\n",
              GetParam().c_str(), mpg.rmse_penumbra, hard.rmse_penumbra, pcf.rmse_penumbra, mpg.rmse, hard.rmse,
              pcf.rmse);
  ASSERT_GT(mpg.penumbra_pixels, 200u);
  EXPECT_LT(mpg.rmse_penumbra, 0.35 * std::min(hard.rmse_penumbra, pcf.rmse_penumbra));
  EXPECT_LT(mpg.rmse, std::min(hard.rmse, pcf.rmse));
}

INSTANTIATE_TEST_SUITE_P(Scenes, MpgReference, ::testing::Values("ball", "fence", "palms"),
                         [](const auto& info) { return info.param; });

// The physical mapping with each alteration, and the paper's mapping for comparison, on the
// fence (thin shadow lines, contact at the pickets' feet). Measured penumbra RMSE: physical 0.052
// (pcf), 0.053 (gaussian), 0.051 (multipass); paper mapping 0.184; hard 0.277. Bounds: 0.062 for
// the physical mapping (measured + ~15% for rasterisation differences between drivers); the
// paper's mapping (Dp 3, Dm 200, Figure 5, tuned for another scale) only below hard shadows.
TEST(MpgReference, PhysicalMappingBoundsPerAlteration) {
  ReferenceFrame f("fence");
  const double hard = f.errors("hard").rmse_penumbra;
  for (const std::string& alteration : test::alterations()) {
    const double e = f.errors("mpg", {"mapping=physical", "alteration=" + alteration}).rmse_penumbra;
    std::printf("[ measure  ] fence, physical, %s: penumbra RMSE %.4f\n", alteration.c_str(), e);
    EXPECT_LT(e, 0.062) << alteration;
  }
  const double paper = f.errors("mpg", {"mapping=paper", "alteration=multipass"}).rmse_penumbra;
  std::printf("[ measure  ] fence, paper mapping, multipass: penumbra RMSE %.4f (hard %.4f)\n", paper, hard);
  EXPECT_LT(paper, hard);
}

// The physical mapping's spot-light branch (perspective shadow map, w = (d_r - d_b) size / d_b at
// the receiver): the ball under a spot light at the sun's emitter position, cone half-angle 45
// degrees. Measured penumbra RMSE: mpg 0.030, hard 0.275, pcf 0.201; asserted like the defaults,
// at most 0.35 x the better of hard and PCF.
TEST(MpgReference, SpotLightPhysicalMappingBeatsHardAndPcf) {
  scene::Scene scene = test::make_scene("ball");
  scene.light.type = scene::LightType::spot;
  scene.light.spot_angle = glm::radians(45.0f);
  ReferenceFrame f(scene);
  const double mpg = f.errors("mpg").rmse_penumbra;
  const double hard = f.errors("hard").rmse_penumbra;
  const double pcf = f.errors("pcf").rmse_penumbra;
  std::printf("[ measure  ] spot-lit ball penumbra RMSE: mpg %.4f, hard %.4f, pcf %.4f\n", mpg, hard, pcf);
  EXPECT_LT(mpg, 0.35 * std::min(hard, pcf));
}

// The footprint S (pass 2 prefiltered in light space up to half a pixel's spread; not in the
// paper) against the one-texel bilinear S, on the scenes whose thin casters throw penumbrae a few
// pixels wide at this size. Measured penumbra RMSE (llvmpipe, 320x180): showcase 0.058 against
// 0.134, fence 0.051 against 0.093 (poles 0.039 against 0.096, but under 1% of its receivers at
// this size). Asserted: at most 0.7 x the bilinear S's.
class MpgFootprint : public ::testing::TestWithParam<std::string> {};

TEST_P(MpgFootprint, PrefilteredSIsNearerTheReferenceThanTheOneTexelS) {
  ReferenceFrame f(GetParam());
  const metrics::MaskErrors footprint = f.errors("mpg", {"shadow_test=footprint"});
  const metrics::MaskErrors bilinear = f.errors("mpg", {"shadow_test=bilinear"});
  std::printf("[ measure  ] %s penumbra RMSE: footprint S %.4f, bilinear S %.4f\n", GetParam().c_str(),
              footprint.rmse_penumbra, bilinear.rmse_penumbra);
  ASSERT_GT(footprint.penumbra_pixels, 200u);
  EXPECT_LT(footprint.rmse_penumbra, 0.7 * bilinear.rmse_penumbra);
}

INSTANTIATE_TEST_SUITE_P(ThinCasters, MpgFootprint, ::testing::Values("showcase", "fence"),
                         [](const auto& info) { return info.param; });
