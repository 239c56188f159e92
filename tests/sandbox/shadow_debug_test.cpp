// Shadow debug geometry: the frustum's edges are its NDC cube's, projection clips what passes
// behind the camera, and the blocker-search region of a receiver under a sun is the emitter's
// disk (its diameter in shadow-map uv) around the receiver, convex.
#include <gtest/gtest.h>

#include <algorithm>

#include "sandbox/shadow_debug.h"
#include "scene/scene.h"

namespace penumbra::sandbox {
namespace {

scene::Bounds unit_box() {
  scene::Bounds b;
  b.extend(glm::vec3(-1.0f));
  b.extend(glm::vec3(1.0f));
  return b;
}

TEST(ShadowDebug, FrustumEdgesAreTheNdcCubesEdges) {
  const scene::Light sun = scene::directional_light_for(unit_box(), glm::vec3(0.3f, -1.0f, 0.2f), 0.05f);
  const scene::ShadowFrustum f = scene::shadow_frustum(sun, unit_box());
  const std::vector<Segment> s = frustum_segments(f);
  ASSERT_EQ(s.size(), 12u);
  for (const Segment& e : s)
    for (const glm::vec3& p : {e.first, e.second}) {
      const glm::vec4 c = f.view_proj * glm::vec4(p, 1.0f);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(std::abs(c[i] / c.w), 1.0f, 1e-3f);
    }
  EXPECT_EQ(emitter_segments(sun, 16).size(), 17u);
}

TEST(ShadowDebug, ProjectionClipsSegmentsBehindTheCamera) {
  const scene::Camera cam = scene::Camera::look_at({0, 0, 5}, {0, 0, 0}, glm::radians(60.0f));
  auto in_front = project_segments({{{-1, 0, 0}, {1, 0, 0}}}, cam, 200, 100);
  ASSERT_EQ(in_front.size(), 1u);
  EXPECT_NEAR(in_front[0].first.y, 50.0f, 1e-3f);
  EXPECT_LT(in_front[0].first.x, 100.0f);
  EXPECT_GT(in_front[0].second.x, 100.0f);
  EXPECT_TRUE(project_segments({{{0, 0, 6}, {1, 0, 7}}}, cam, 200, 100).empty()) << "wholly behind";
  auto crossing = project_segments({{{0, 1, 0}, {0, 1, 10}}}, cam, 200, 100);
  ASSERT_EQ(crossing.size(), 1u);
  for (const glm::vec2& p : {crossing[0].first, crossing[0].second}) {
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
  }
}

TEST(ShadowDebug, BlockerRegionUnderASunIsTheEmitterDiskAroundTheReceiver) {
  scene::Light sun = scene::directional_light_for(unit_box(), glm::vec3(0.0f, -1.0f, 0.0f), 0.1f);
  const scene::ShadowFrustum f = scene::shadow_frustum(sun, unit_box());
  ASSERT_TRUE(f.orthographic);
  const glm::vec3 receiver(0.0f, -1.0f, 0.0f);
  const std::vector<glm::vec2> hull = blocker_search_region(receiver, sun, f, 32);
  ASSERT_GE(hull.size(), 16u);
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (const glm::vec2& p : hull) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  EXPECT_NEAR(hi.x - lo.x, sun.size / f.width_world, 0.02f * sun.size / f.width_world);
  for (size_t i = 0; i < hull.size(); ++i) {  // convex, counter-clockwise
    const glm::vec2 a = hull[i], b = hull[(i + 1) % hull.size()], c = hull[(i + 2) % hull.size()];
    EXPECT_GE((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x), -1e-9f);
  }
  // A receiver outside the map has no region.
  EXPECT_TRUE(blocker_search_region({50.0f, 0.0f, 0.0f}, sun, f).empty());
}

// The penumbra readout's arithmetic: shadow-map depth back to distance from the light, and the
// similar-triangles width.
TEST(ShadowDebug, DepthBackToLightDistanceAndPenumbraWidth) {
  scene::Light sun;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  sun.position = -sun.direction * 20.0f;
  const scene::ShadowFrustum f = scene::shadow_frustum(sun, {glm::vec3(-5.0f), glm::vec3(5.0f)});
  for (float along : {15.0f, 20.0f, 24.0f}) {
    const glm::vec3 p = sun.position + sun.direction * along;
    EXPECT_NEAR(light_distance(f, shadow_depth(f, p)), along, 1e-3f) << along;
  }
  EXPECT_NEAR(penumbra_width(0.7f, 14.0f, 11.8f), 0.7f * 2.2f / 11.8f, 1e-6f);
  EXPECT_EQ(penumbra_width(0.7f, 10.0f, 12.0f), 0.0f);  // the "blocker" is behind the receiver
  EXPECT_EQ(penumbra_width(0.7f, 10.0f, 0.0f), 0.0f);
}

}  // namespace
}  // namespace penumbra::sandbox
