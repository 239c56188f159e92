// Contact hardening (Cherry & Kooima, sections 3-4, Figures 4-5): for every alteration of pass 4,
// the penumbra of the ball's ground shadow widens as the ball rises, and its width follows the
// ray-traced reference's. Probe: ball_probe.h.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ball_probe.h"
#include "mpg_rig.h"
#include "mpg_settings.h"
#include "raytraced_reference.h"

using namespace penumbra;

namespace {

// A light 1.5 m across instead of the scene's 0.6 m: the penumbra then spans 3-6 px at 224x168
// instead of 2-4 px, well above the quarter-pixel resolution of the width.
scene::Scene ball_at(float height) { return test::make_scene("ball", {{"ball_height", height}, {"light_size", 1.5f}}); }

float reference_width(test::MpgRig& rig, const scene::Scene& scene) {
  std::vector<glm::vec3> positions, normals;
  metrics::CoverageMask coverage;
  rig.gbuffer(positions, normals, coverage);
  auto rs = reference::RayScene::build(scene);
  EXPECT_TRUE(rs);
  metrics::MaskImage ref = reference::trace_visibility(*rs, rig.session().light(), positions, normals, test::kWidth,
                                                       test::kHeight, {.samples = 128}, coverage);
  Result<float> w = test::ball_penumbra_width(ref, rig.world_y());
  EXPECT_TRUE(w) << w.error().to_string();
  return w ? *w : -1.0f;
}

}  // namespace

class MpgContactHardening : public ::testing::TestWithParam<std::string> {};

// Measured (llvmpipe, 224x168, 1024^2 map), 10%-90% width in pixels at ball heights 0.1 / 0.5 /
// 1.0 m: reference (128 light samples) 3.12 / 4.37 / 5.64; pcf 3.39 / 4.42 / 5.46; gaussian
// 3.46 / 4.45 / 5.57; multipass 3.37 / 4.50 / 5.48. Asserted: each step widens the penumbra by
// more than 15% (the reference: 40% and 29%), and every width is within 20% of the reference's
// (measured: at most 11%, at the lowest ball, where one pixel of blur is a large fraction).
TEST_P(MpgContactHardening, PenumbraWidensWithBallHeightLikeTheReference) {
  const std::string alteration = GetParam();
  test::MpgRig rig(test::kWidth, test::kHeight, test::kShadowSize);
  rig.set_scene(ball_at(0.1f));
  // The default dilation (29 pixels) is sized for 1920x1080; at this image's height the paper's
  // scale of outer penumbra is a few pixels (docs: techniques/mpg/README.md, 1080p sweep).
  rig.set({"alteration=" + alteration, "dilation_kernel=9"});
  float previous = 0.0f;
  for (float h : {0.1f, 0.5f, 1.0f}) {
    const scene::Scene scene = ball_at(h);
    rig.set_scene(scene);
    rig.render();
    metrics::MaskImage mask = rig.shadow_mask();
    Result<float> w = test::ball_penumbra_width(mask, rig.world_y());
    ASSERT_TRUE(w) << alteration << " at ball_height " << h << ": " << w.error().to_string();
    const float truth = reference_width(rig, scene);
    std::printf("[ measure  ] %s, ball_height %.1f m: penumbra width %.2f px (reference %.2f px)\n",
                alteration.c_str(), h, *w, truth);
    test::save_for_inspection("ball_" + alteration + "_h" + std::to_string(h), mask);
    EXPECT_GT(*w, 1.15f * previous) << alteration << " at ball_height " << h;
    EXPECT_LT(std::abs(*w - truth), 0.2f * truth) << alteration << " at ball_height " << h;
    previous = *w;
  }
}

INSTANTIATE_TEST_SUITE_P(Alterations, MpgContactHardening, ::testing::ValuesIn(test::alterations()),
                         [](const auto& info) { return info.param; });
