// The MSM plugin's tests (Penumbra::test_support): against the ray-traced reference of the same
// frame, MSM (contact-hardening, the default) is nearer the truth than the built-in hard shadow
// map and PCF on every built-in scene, and nearer than the paper's plain MSM (PCSS is rendered
// and reported beside them); lit receivers stay lit; the 16-bit map gives the 32-bit map's shadow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "scene/builtin_scenes.h"
#include "techniques/builtin_techniques.h"
#include "test_support/reference_comparison.h"
#include "test_support/technique_rig.h"

namespace {

using namespace penumbra::test;

constexpr int kW = 160, kH = 120, kShadow = 1024;

TechniqueRig make_rig() {
  return TechniqueRig({.width = kW, .height = kH, .shadow_size = kShadow,
                       .techniques = penumbra::register_builtin_techniques, .plugin_dirs = {MSM_PLUGIN_DIR}});
}

class MsmOnEveryScene : public ::testing::TestWithParam<std::string> {};

TEST_P(MsmOnEveryScene, NearerTheTruthThanHardPcfAndPlainMsm) {
  TechniqueRig rig = make_rig();
  const penumbra::scene::Scene s = builtin_scene(GetParam());
  const RenderedFrame msm = rig.render_frame(s, "msm");
  const penumbra::metrics::MaskImage truth = traced_reference(s, msm);
  const auto error = [&](const std::string& technique, const std::vector<std::string>& settings = {}) {
    return penumbra_rmse(rig.render_frame(s, technique, settings).mask, truth, msm);
  };
  const double e_msm = penumbra_rmse(msm.mask, truth, msm);
  const double e_plain = error("msm", {"contact_hardening=false"}), e_pcf = error("pcf");
  const double e_pcss = error("pcss"), e_hard = error("hard");
  std::printf("%s: penumbra RMSE msm %.4f, plain msm %.4f, hard %.4f, pcf %.4f, pcss %.4f\n", GetParam().c_str(),
              e_msm, e_plain, e_hard, e_pcf, e_pcss);
  EXPECT_LT(e_msm, e_hard);
  EXPECT_LT(e_msm, e_pcf);
  EXPECT_LT(e_msm, e_plain) << "the blockers' height sizes the filter better than one width for all";
}

// The built-in scenes one moment map holds: the room's lamp needs six faces, which msm refuses
// (MsmRefusesAPointLightInsideTheScene), and the 200 m avenue is made for cascades, which it
// refuses too (one 1024^2 map over it has texels of 20 cm under slats of 10 cm).
std::vector<std::string> one_map_scenes() {
  std::vector<std::string> names;
  for (const std::string& name : penumbra::scene::builtin_scene_names()) {
    const penumbra::scene::Scene s = builtin_scene(name);
    if (!penumbra::scene::shadow_frustum(s.light, s.bounds).six_faces && name != "avenue") names.push_back(name);
  }
  return names;
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, MsmOnEveryScene, ::testing::ValuesIn(one_map_scenes()));

// Its moments are a light-view pass's colour target: a frame whose light needs six faces is a
// bad-input Error naming the techniques that take it, not a moment map of one face.
TEST(Msm, RefusesAPointLightInsideTheScene) {
  TechniqueRig rig = make_rig();
  rig.set_scene(builtin_scene("room"));
  rig.use("msm");
  penumbra::Status s = rig.try_render();
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().to_string().find("inside the scene bounds"), std::string::npos) << s.error().to_string();
  EXPECT_NE(s.error().to_string().find("pcss"), std::string::npos) << s.error().to_string();
  EXPECT_EQ(s.error().exit_code(), 2);
}

// Cascades keep each in a tile of the map, which a light-view pass's colour targets do not follow.
TEST(Msm, RefusesCascades) {
  TechniqueRig rig = make_rig();
  rig.set_scene(builtin_scene("avenue"));
  ASSERT_TRUE(rig.session().set_cascades({.count = 4}));
  rig.use("msm");
  penumbra::Status s = rig.try_render();
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().to_string().find("cascade"), std::string::npos) << s.error().to_string();
  EXPECT_EQ(s.error().exit_code(), 2);
}

TEST(Msm, LitReceiversStayLitAndTheBallCastsAnUmbra) {
  TechniqueRig rig = make_rig();
  const RenderedFrame f = rig.render_frame(builtin_scene("ball"), "msm");
  int lit = 0, dark = 0, receivers = 0;
  for (size_t i = 0; i < f.mask.pixels.size(); ++i) {
    if (!f.coverage[i]) {
      EXPECT_EQ(f.mask.pixels[i], 1.0f) << "background";
      continue;
    }
    ++receivers;
    lit += f.mask.pixels[i] >= 0.99f;
    dark += f.mask.pixels[i] <= 0.05f;
  }
  EXPECT_GT(lit, receivers / 2) << "most of the ground is lit and stays so (no acne)";
  EXPECT_GT(dark, 20) << "the ball's umbra";
}

TEST(Msm, SixteenBitMomentsGiveTheThirtyTwoBitShadow) {
  TechniqueRig rig = make_rig();
  const penumbra::scene::Scene s = builtin_scene("ball");
  const RenderedFrame half = rig.render_frame(s, "msm", {"moment_format=RGBA16"});
  const RenderedFrame full = rig.render_frame(s, "msm", {"moment_format=RGBA32F"});
  ASSERT_EQ(half.mask.pixels.size(), full.mask.pixels.size());
  double worst = 0.0;
  for (size_t i = 0; i < half.mask.pixels.size(); ++i)
    worst = std::max(worst, static_cast<double>(std::abs(half.mask.pixels[i] - full.mask.pixels[i])));
  EXPECT_LT(worst, 0.1) << "the optimised quantisation keeps the moments";
}

}  // namespace
