// Every variant and mask switch compiles, renders and writes a mask in [0, 1] with both lit and
// shadowed pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "pmchss_fixture.h"
#include "scene/builtin_scenes.h"

using namespace penumbra;

TEST(PmchssSmoke, EveryVariantRendersAValidMask) {
  test::PmchssRig rig(192, 144, 1024);
  auto scene = scene::make_builtin_scene("colonnade");
  ASSERT_TRUE(scene);
  rig.set_scene(*scene);
  for (const char* variant : {"regular", "penumbra_mask", "min_filter"}) {
    for (const char* checker : {"false", "true"}) {
      rig.set({std::string("variant=") + variant, std::string("checkerboard=") + checker});
      rig.render();
      metrics::MaskImage m = rig.shadow_mask();
      ASSERT_EQ(m.width, 192);
      auto [lo, hi] = std::minmax_element(m.pixels.begin(), m.pixels.end());
      EXPECT_GE(*lo, 0.0f);
      EXPECT_LE(*hi, 1.0f);
      EXPECT_LT(*lo, 0.05f) << variant;
      EXPECT_GT(*hi, 0.95f) << variant;
      std::string tag = std::string(variant) + (checker[0] == 't' ? "_checker" : "");
      test::save_for_inspection("colonnade_" + tag + "_mask", m);
      test::save_for_inspection("colonnade_" + tag + "_color", rig.read("color"));
    }
  }
  // The mask's structural switches: half resolution, max filter, no blur, default 1.
  for (std::vector<std::string> config :
       {std::vector<std::string>{"variant=penumbra_mask", "checkerboard=false", "mask_divisor=2"},
        {"mask_max_filter=true"}, {"mask_blur=false"}, {"mask_max_filter=false", "mask_default_one=true"},
        {"mask_divisor=4", "mask_blur=true", "mask_default_one=false"}}) {
    rig.set(config);
    rig.render();
    metrics::MaskImage m = rig.shadow_mask();
    auto [lo, hi] = std::minmax_element(m.pixels.begin(), m.pixels.end());
    EXPECT_LT(*lo, 0.05f) << config.front();
    EXPECT_GT(*hi, 0.95f) << config.front();
  }
  EXPECT_EQ(rig.read("penumbra_mask").width, 192 / 4);
  test::save_for_inspection("colonnade_penumbra_mask_raw", rig.read("penumbra_mask_raw"));
  test::save_for_inspection("colonnade_penumbra_mask_blurred", rig.read("penumbra_mask"));
  test::save_for_inspection("colonnade_blocker_depth", rig.read("blocker_depth"));
}
