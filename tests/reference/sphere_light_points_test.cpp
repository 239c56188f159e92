// GL-free properties of the raster reference's point-light samples: seen along any direction they
// spread uniformly over the sphere's disk, as the ray tracer's samples do for every receiver.
#include <gtest/gtest.h>

#include <cmath>

#include "techniques/reference/sphere_light_points.h"

using namespace penumbra;

namespace {

scene::Light sphere(float size) {
  scene::Light l;
  l.type = scene::LightType::point;
  l.position = glm::vec3(1.0f, 2.0f, -3.0f);
  l.size = size;
  return l;
}

}  // namespace

TEST(SphereLightPoints, SeenAlongAnyDirectionTheyAreUniformOverTheDisk) {
  const scene::Light light = sphere(0.5f);
  const float r = light.radius();
  const int n = 4096;
  const std::vector<glm::vec3> points = reference::sphere_light_points(light, n, 7);
  ASSERT_EQ(points.size(), static_cast<size_t>(n));
  for (const glm::vec3& p : points) EXPECT_LE(glm::length(p - light.position), r * 1.0001f);
  for (glm::vec3 axis : {glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), glm::vec3(0.3f, -0.8f, 0.5f)}) {
    axis = glm::normalize(axis);
    // Uniform over the disk: a fraction q of the points within r sqrt(q) of the axis, for every q.
    for (float q : {0.1f, 0.25f, 0.5f, 0.75f, 0.9f}) {
      int inside = 0;
      for (const glm::vec3& p : points) {
        const glm::vec3 d = p - light.position;
        const float across = glm::length(d - glm::dot(d, axis) * axis);
        inside += across < r * std::sqrt(q);
      }
      EXPECT_NEAR(inside / static_cast<double>(n), q, 0.015) << "q " << q;
    }
    // And centred: no side of the disk favoured.
    glm::vec3 mean(0.0f);
    for (const glm::vec3& p : points) mean += (p - light.position) / static_cast<float>(n);
    EXPECT_LT(glm::length(mean), 0.02f * r);
  }
}

TEST(SphereLightPoints, ALightOfNoSizeIsItsCentreAndTheSeedMovesThePoints) {
  for (const glm::vec3& p : reference::sphere_light_points(sphere(0.0f), 16, 0)) EXPECT_EQ(p, sphere(0.0f).position);
  const auto a = reference::sphere_light_points(sphere(1.0f), 16, 0);
  const auto b = reference::sphere_light_points(sphere(1.0f), 16, 1);
  EXPECT_EQ(a, reference::sphere_light_points(sphere(1.0f), 16, 0));
  EXPECT_NE(a, b);
  EXPECT_TRUE(reference::sphere_light_points(sphere(1.0f), 0, 0).empty());
}
