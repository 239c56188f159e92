// What the one-map techniques do with a point light (which the engine gained for esm): outside
// the scene bounds they shadow it through one frustum fitted to the bounds; inside the bounds
// every frame is a clear bad-input Error, never a crash or a garbage mask.
#include <gtest/gtest.h>

#include <algorithm>

#include "esm_rig.h"
#include "scene/builtin_scenes.h"

using namespace penumbra;

namespace {

scene::Scene ball_with_point_light(const glm::vec3& position) {
  scene::Scene s = *scene::make_builtin_scene("ball");
  s.light.type = scene::LightType::point;
  s.light.position = position;
  s.light.size = 0.0f;
  return s;
}

const char* kOneMapTechniques[] = {"hard", "pcf", "pcss", "pmchss"};

}  // namespace

TEST(PointLightOneMap, OutsideTheBoundsCastsAShadowThroughAFittedFrustum) {
  test::EsmRig rig(96, 72, 512);
  rig.set_scene(ball_with_point_light({0.0f, 5.0f, -1.5f}));
  for (const char* t : kOneMapTechniques) {
    rig.use(t);
    rig.render();
    const metrics::MaskImage m = rig.shadow_mask();
    ASSERT_EQ(m.width, 96) << t;
    const auto [lo, hi] = std::minmax_element(m.pixels.begin(), m.pixels.end());
    EXPECT_LT(*lo, 0.1f) << t << ": the ball casts a shadow";
    EXPECT_EQ(*hi, 1.0f) << t << ": the ground around it is lit";
  }
}

TEST(PointLightOneMap, InsideTheBoundsIsABadInputErrorNamingTheFix) {
  test::EsmRig rig(64, 48, 256);
  rig.set_scene(ball_with_point_light({0.0f, 1.0f, 1.0f}));
  for (const char* t : kOneMapTechniques) {
    rig.use(t);
    Status s = rig.try_render();
    ASSERT_FALSE(s) << t;
    const std::string msg = s.error().to_string();
    EXPECT_NE(msg.find("inside the scene bounds"), std::string::npos) << t << ": " << msg;
    EXPECT_NE(msg.find("esm"), std::string::npos) << t << ": " << msg;
    EXPECT_EQ(s.error().exit_code(), 2) << t;
  }
  rig.use("reference");  // raster by default: refuses point lights and names the method that works
  Status s = rig.try_render();
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().to_string().find("method=raytraced"), std::string::npos) << s.error().to_string();
}
