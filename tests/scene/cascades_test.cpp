// GL-free properties of cascaded shadow maps (scene/cascades.h): the split scheme, every slice
// held by its cascade with the margin, texel-snapped (stable) squares, and bad settings refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scene/builtin_scenes.h"
#include "scene/cascades.h"

using namespace penumbra;

namespace {

constexpr float kAspect = 16.0f / 9.0f;
constexpr int kMap = 2048;

scene::Scene avenue() { return *scene::make_builtin_scene("avenue"); }

scene::ShadowCascades cascades_of(const scene::Scene& s, const scene::Camera& camera, int count = 4) {
  const scene::ShadowFrustum one = scene::shadow_frustum(s.light, s.bounds);
  auto c = scene::shadow_cascades(s.light, one, camera, kAspect, s.bounds, {.count = count}, kMap);
  EXPECT_TRUE(c) << c.error().to_string();
  return c ? *c : scene::ShadowCascades{};
}

// Where a world point falls in cascade i's tile, in texels.
glm::vec2 texel_position(const scene::ShadowCascades& c, int i, const glm::vec3& world) {
  const glm::vec4 clip = c.tiles[i].view_proj * glm::vec4(world, 1.0f);
  return (glm::vec2(clip) * 0.5f + 0.5f) * static_cast<float>(c.tiles[i].size);
}

}  // namespace

TEST(Cascades, SplitsFollowThePracticalSplitScheme) {
  const auto linear = scene::cascade_splits(1.0f, 101.0f, 4, 0.0f);
  const auto log = scene::cascade_splits(1.0f, 100.0f, 2, 1.0f);
  for (int i = 0; i <= 4; ++i) EXPECT_NEAR(linear[i], 1.0f + 25.0f * i, 1e-4f);
  EXPECT_NEAR(log[1], 10.0f, 1e-4f);  // n (f / n)^(1/2)
  const auto mixed = scene::cascade_splits(0.1f, 200.0f, 4, 0.9f);
  EXPECT_EQ(mixed[0], 0.1f);
  EXPECT_EQ(mixed[4], 200.0f);
  for (int i = 0; i < 4; ++i) EXPECT_LT(mixed[i], mixed[i + 1]);
}

TEST(Cascades, EverySliceIsHeldByItsCascadeWithTheMargin) {
  const scene::Scene s = avenue();
  const scene::ShadowCascades c = cascades_of(s, s.camera);
  ASSERT_EQ(c.count, 4);
  const float ty = std::tan(0.5f * s.camera.fov_y), tx = ty * kAspect;
  const glm::mat4 to_world = glm::inverse(s.camera.view());
  for (int i = 0; i < 4; ++i) {
    EXPECT_GT(c.width_world[i], 0.0f);
    if (i > 0) EXPECT_GE(c.width_world[i], c.width_world[i - 1]) << "cascades grow with distance";
    EXPECT_EQ(c.tiles[i].size, kMap / 2);
    // A slice wider than the scene's own map gets that map's square, which holds the scene (not
    // the slice's corners beyond it).
    if (c.width_world[i] >= scene::shadow_frustum(s.light, s.bounds).width_world) continue;
    for (float z : {c.splits[i], c.splits[i + 1]})
      for (float sx : {-1.0f, 1.0f})
        for (float sy : {-1.0f, 1.0f}) {
          const glm::vec3 corner = glm::vec3(to_world * glm::vec4(sx * tx * z, sy * ty * z, -z, 1.0f));
          const glm::vec4 clip = c.tiles[i].view_proj * glm::vec4(corner, 1.0f);
          EXPECT_LE(std::max(std::abs(clip.x), std::abs(clip.y)), 1.0f - scene::kCascadeMarginOfHalfSide + 1e-4f)
              << "cascade " << i << " at depth " << z;
          EXPECT_LE(scene::cascade_of(c, corner), i);
        }
  }
  // The tiles are the map's four quadrants.
  EXPECT_EQ(c.tiles[3].origin, glm::ivec2(kMap / 2));
}

// Stable cascades: a camera moved by less than a texel (or by many) keeps each square's size, and
// every world point keeps its place inside its texel (the square moves by whole texels).
TEST(Cascades, AMovingCameraMovesEachSquareByWholeTexels) {
  const scene::Scene s = avenue();
  const scene::ShadowCascades before = cascades_of(s, s.camera);
  const glm::vec3 probe(0.37f, 0.0f, -5.21f);
  for (const glm::vec3& move : {glm::vec3(0.004f, 0.0f, 0.0f), glm::vec3(0.013f, 0.002f, -0.021f),
                                glm::vec3(1.7f, 0.0f, 0.6f)}) {
    scene::Camera moved = s.camera;
    moved.position += move;
    moved.yaw += 0.01f;  // turning does not change a slice's sphere either
    const scene::ShadowCascades after = cascades_of(s, moved);
    for (int i = 0; i < 4; ++i) {
      EXPECT_FLOAT_EQ(after.width_world[i], before.width_world[i]) << "cascade " << i;
      const glm::vec2 a = texel_position(before, i, probe), b = texel_position(after, i, probe);
      const glm::vec2 shift = b - a;
      EXPECT_NEAR(shift.x, std::round(shift.x), 2e-2f) << "cascade " << i << " moved by a fraction of a texel";
      EXPECT_NEAR(shift.y, std::round(shift.y), 2e-2f) << "cascade " << i;
    }
  }
}

TEST(Cascades, SettingsOutOfRangeAndNonDirectionalLightsAreRefused) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const scene::CascadeSettings& bad :
       {scene::CascadeSettings{.count = 0}, scene::CascadeSettings{.count = 5},
        scene::CascadeSettings{.count = 2, .split_lambda = -0.1f}, scene::CascadeSettings{.count = 2, .split_lambda = nan},
        scene::CascadeSettings{.count = 2, .blend = 0.6f}}) {
    Status st = scene::check_cascade_settings(bad);
    ASSERT_FALSE(st);
    EXPECT_EQ(st.error().exit_code(), 2);
  }
  EXPECT_NE(scene::check_cascade_settings({.count = 5}).error().to_string().find("1..4"), std::string::npos);
  const scene::Scene room = *scene::make_builtin_scene("room");
  const scene::ShadowFrustum one = scene::shadow_frustum(room.light, room.bounds);
  auto c = scene::shadow_cascades(room.light, one, room.camera, kAspect, room.bounds, {.count = 4}, kMap);
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().to_string().find("directional"), std::string::npos) << c.error().to_string();
  // One cascade is the scene's map, for any light.
  auto single = scene::shadow_cascades(room.light, one, room.camera, kAspect, room.bounds, {.count = 1}, kMap);
  ASSERT_TRUE(single);
  EXPECT_EQ(single->count, 1);
}
