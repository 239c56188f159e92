// The light gizmo's disk: zenith at the centre, horizon at the rim, up = where the camera looks.
#include <gtest/gtest.h>

#include "sandbox/light_gizmo.h"

namespace penumbra::sandbox {
namespace {

TEST(LightGizmo, ZenithIsTheCentreAndUpIsTheCameraDirection) {
  scene::Camera cam;
  cam.yaw = 0.7f;
  EXPECT_NEAR(glm::length(gizmo_point({0.0f, -1.0f, 0.0f}, cam)), 0.0f, 1e-5f);
  // A light low in front of the camera (shining back towards it) sits near the top of the rim.
  const glm::vec3 ahead = glm::normalize(glm::vec3(std::sin(cam.yaw), 0.05f, -std::cos(cam.yaw)));
  const glm::vec2 p = gizmo_point(-ahead, cam);
  EXPECT_NEAR(p.x, 0.0f, 1e-4f);
  EXPECT_GT(p.y, 0.9f);
}

TEST(LightGizmo, PointAndDirectionAreInverse) {
  scene::Camera cam;
  cam.yaw = -1.2f;
  for (const glm::vec2 p : {glm::vec2(0.3f, -0.2f), glm::vec2(-0.6f, 0.5f), glm::vec2(0.0f, 0.9f)}) {
    const glm::vec3 d = gizmo_direction(p, cam);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
    EXPECT_LT(d.y, 0.0f);  // it shines down
    const glm::vec2 back = gizmo_point(d, cam);
    EXPECT_NEAR(back.x, p.x * 89.0f / 90.0f, 1e-4f);
    EXPECT_NEAR(back.y, p.y * 89.0f / 90.0f, 1e-4f);
  }
  // Beyond the rim: on the rim, just above the horizon.
  EXPECT_NEAR(gizmo_direction({3.0f, 0.0f}, cam).y, -std::cos(glm::radians(89.0f)), 1e-5f);
}

}  // namespace
}  // namespace penumbra::sandbox
