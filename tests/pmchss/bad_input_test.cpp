// Bad input gives clear errors, never garbage.
#include <gtest/gtest.h>

#include "pmchss_fixture.h"
#include "pmchss_settings.h"

using namespace penumbra;

TEST(PmchssBadInput, OutOfRangeParameterNamesTheRange) {
  test::PmchssRig rig(64, 48, 512);
  rig.set_scene(test::make_scene("ball"));
  Status s = rig.session().set_param("penumbra_kernel_scale=3");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("penumbra_kernel_scale"), std::string::npos) << s.error().message;
  EXPECT_NE(s.error().message.find("[1, 2]"), std::string::npos) << s.error().message;
  s = rig.session().set_param("blocker_samples=0");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("[4, 64]"), std::string::npos) << s.error().message;
  EXPECT_EQ(rig.session().params().get_real("penumbra_kernel_scale"), 1.2);  // unchanged
}

// The blocker search radius (1.2 x the paper's 0.002 UV) must cover a texel: 417 texels at
// least. 256 is refused by name; 512 works.
TEST(PmchssBadInput, TooSmallShadowMapIsAClearError) {
  test::PmchssRig rig(64, 48, 256);
  rig.set_scene(test::make_scene("ball"));
  rig.set({"shadow_filter_max_size=0.002"});
  for (const char* variant : {"regular", "penumbra_mask", "min_filter"}) {
    rig.set({std::string("variant=") + variant});
    Status s = rig.session().render();
    ASSERT_FALSE(s) << variant;
    const std::string& m = s.error().message;
    EXPECT_NE(m.find("shadow map 256x256"), std::string::npos) << m;
    EXPECT_NE(m.find("shadow_filter_max_size"), std::string::npos) << m;
    EXPECT_NE(m.find("at least 417 texels"), std::string::npos) << m;
  }
  ASSERT_TRUE(rig.session().set_shadow_size(512));
  Status s = rig.session().render();
  EXPECT_TRUE(s) << s.error().to_string();
}
