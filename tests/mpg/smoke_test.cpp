// Every alteration and switch compiles, renders and writes a mask in [0, 1] with lit and umbra
// pixels; the debug views show what they say they show.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "mpg_rig.h"
#include "mpg_settings.h"

using namespace penumbra;

TEST(MpgSmoke, EveryConfigurationRendersAValidMask) {
  test::MpgRig rig(160, 120, 1024);
  rig.set_scene(test::make_scene("colonnade"));
  for (const std::string& alteration : test::alterations()) {
    for (const std::vector<std::string>& config :
         {std::vector<std::string>{"dilation=true", "umbra_early_out=false", "mapping=physical"},
          {"dilation=false", "umbra_early_out=true", "umbra_neighbourhood=31"},
          {"mapping=paper", "anisotropic=false", "depth_aware=false", "shadow_test=nearest"},
          {"kernel_mode=fixed", "kernel_sampling=dense", "max_kernel=9", "dilation=true", "umbra_early_out=false",
           "mapping=physical", "anisotropic=true", "depth_aware=true", "shadow_test=bilinear"}}) {
      SCOPED_TRACE(alteration + " " + config.front());
      rig.set({"alteration=" + alteration});
      rig.set(config);
      rig.render();
      metrics::MaskImage m = rig.shadow_mask();
      ASSERT_EQ(m.width, 160);
      auto [lo, hi] = std::minmax_element(m.pixels.begin(), m.pixels.end());
      EXPECT_GE(*lo, 0.0f);
      EXPECT_LE(*hi, 1.0f);
      EXPECT_LT(*lo, 0.02f);
      EXPECT_EQ(*hi, 1.0f);
    }
    rig.set({"kernel_mode=progressive", "kernel_sampling=poisson", "max_kernel=19"});
  }
}

// The alpha-masked palms: the leaflet gaps reach the mask (partly lit pixels under the crowns).
TEST(MpgSmoke, PalmFrondShadowsHaveGaps) {
  test::MpgRig rig(160, 120, 1024);
  rig.set_scene(test::make_scene("palms"));
  rig.render();
  metrics::MaskImage m = rig.shadow_mask();
  size_t partial = 0, umbra = 0;
  for (float v : m.pixels) {
    partial += v > 0.05f && v < 0.95f;
    umbra += v <= 0.02f;
  }
  EXPECT_GT(partial, 500u);
  EXPECT_GT(umbra, 100u);
  test::save_for_inspection("palms_mask", m);
  test::save_for_inspection("palms_color", rig.read_rgba("color"));
}

// Figure 4's view follows the final mask pixel by pixel: white where lit (>= 0.99), grey hatching
// where umbra (<= 0.01), a dark blue gradient between, black on the background. The D view is
// coloured (heat ramp) exactly where the distance map has D > 0, which happens only on receivers.
TEST(MpgSmoke, DebugViewsShowThePenumbraAndD) {
  test::MpgRig rig(160, 120, 1024);
  rig.set_scene(test::make_scene("ball", {{"light_size", 1.5f}}));
  rig.render();
  metrics::MaskImage mask = rig.shadow_mask();
  metrics::MaskImage depth = rig.read("gbuffer_depth");
  metrics::RgbaImage penumbra = rig.read_rgba("debug_penumbra"), distance = rig.read_rgba("debug_distance");
  ASSERT_EQ(penumbra.width, 160);
  ASSERT_EQ(distance.width, 160);
  size_t counts[4] = {0, 0, 0, 0}, heat = 0;
  for (size_t i = 0; i < mask.pixels.size(); ++i) {
    const uint8_t* p = &penumbra.pixels[i * 4];
    const float v = mask.pixels[i];
    int kind = depth.pixels[i] <= 0.0f ? 0 : v >= 0.99f ? 1 : v <= 0.01f ? 2 : 3;
    ++counts[kind];
    switch (kind) {
      case 0: EXPECT_EQ(p[0] + p[1] + p[2], 0) << i; break;
      case 1: EXPECT_EQ(p[0] + p[1] + p[2], 3 * 255) << i; break;
      case 2: EXPECT_TRUE(p[0] == p[1] && p[1] == p[2] && p[0] > 100 && p[0] < 180) << i; break;
      default: EXPECT_TRUE(p[2] > p[0] && p[0] < 100) << i; break;  // dark blue
    }
    const uint8_t* d = &distance.pixels[i * 4];
    heat += !(d[0] == d[1] && d[1] == d[2]);
  }
  EXPECT_GT(counts[0], 100u);
  EXPECT_GT(counts[2], 50u);
  EXPECT_GT(counts[3], 50u);
  EXPECT_GT(heat, 50u);
  test::save_for_inspection("ball_debug_penumbra", penumbra);
  test::save_for_inspection("ball_debug_distance", distance);
}
