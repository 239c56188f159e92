#include <gtest/gtest.h>

#include "scene/light.h"
#include "scene/scene.h"

using namespace penumbra;

TEST(LightSamples, OnTheEmitterDiskStratifiedAndDeterministic) {
  scene::Light l;
  l.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  l.position = {1.0f, 5.0f, -2.0f};
  l.size = 0.8f;  // diameter
  const auto pts = scene::light_sample_points(l, 256, 7);
  ASSERT_EQ(pts.size(), 256u);
  glm::vec3 mean(0.0f);
  float max_r = 0.0f;
  for (const glm::vec3& p : pts) {
    EXPECT_NEAR(glm::dot(p - l.position, l.direction), 0.0f, 1e-5f);  // in the emitter plane
    max_r = std::max(max_r, glm::length(p - l.position));
    mean += p / 256.0f;
  }
  EXPECT_LE(max_r, 0.4f + 1e-5f);
  EXPECT_GT(max_r, 0.35f);                          // reaches near the rim
  EXPECT_LT(glm::length(mean - l.position), 0.01f);  // stratified: mean ~ centre
  EXPECT_EQ(pts, scene::light_sample_points(l, 256, 7));
  EXPECT_NE(pts, scene::light_sample_points(l, 256, 8));
  EXPECT_EQ(scene::light_sample_points(l, 7, 0).size(), 7u);  // prime counts work too
}

TEST(ShadowFrustum, DirectionalCoversBoundsAndSpotIsPerspective) {
  scene::Bounds b;
  b.extend(glm::vec3(-5, 0, -5));
  b.extend(glm::vec3(5, 2, 5));
  scene::Light l = scene::directional_light_for(b, {-0.3f, -1.0f, -0.2f}, 0.03f);
  scene::ShadowFrustum f = scene::shadow_frustum(l, b);
  EXPECT_TRUE(f.orthographic);
  EXPECT_GT(f.width_world, 10.0f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c(i & 1 ? 5 : -5, i & 2 ? 2 : 0, i & 4 ? 5 : -5);
    const glm::vec4 clip = f.view_proj * glm::vec4(c, 1.0f);
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(clip[k] / clip.w), 1.0f) << "corner " << i;
  }
  l.type = scene::LightType::spot;
  l.spot_angle = glm::radians(60.0f);
  f = scene::shadow_frustum(l, b);
  EXPECT_FALSE(f.orthographic);
  EXPECT_GT(f.near_plane, 0.0f);
  EXPECT_LT(f.near_plane, f.far_plane);
}
