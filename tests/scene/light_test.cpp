#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scene/light.h"
#include "scene/light_faces.h"
#include "scene/scene.h"

using namespace penumbra;

namespace {

// The box |x|, |y|, |z| <= half.
scene::Bounds cube(float half) {
  scene::Bounds b;
  b.extend(glm::vec3(-half));
  b.extend(glm::vec3(half));
  return b;
}

scene::Light light(scene::LightType type, const glm::vec3& position) {
  scene::Light l;
  l.type = type;
  l.position = position;
  return l;
}

}  // namespace

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

// A point light outside the bounds gets one perspective frustum towards the bounds that contains
// every corner; inside the bounds no single frustum can, and the frustum asks for six faces.
TEST(ShadowFrustum, PointLightOutsideBoundsIsAFittedSpotInsideHasSixFaces) {
  scene::Bounds b;
  b.extend(glm::vec3(-5, 0, -5));
  b.extend(glm::vec3(5, 2, 5));
  scene::Light l;
  l.type = scene::LightType::point;
  l.direction = glm::vec3(1, 0, 0);  // not used by a point light's frustum
  l.position = {3.0f, 9.0f, 4.0f};
  scene::ShadowFrustum f = scene::shadow_frustum(l, b);
  EXPECT_FALSE(f.six_faces);
  EXPECT_FALSE(f.orthographic);
  EXPECT_GT(f.tan_half_fov, 0.0f);
  EXPECT_GT(f.near_plane, 0.0f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c(i & 1 ? 5 : -5, i & 2 ? 2 : 0, i & 4 ? 5 : -5);
    const glm::vec4 clip = f.view_proj * glm::vec4(c, 1.0f);
    ASSERT_GT(clip.w, 0.0f) << "corner " << i;
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(clip[k] / clip.w), 1.0f) << "corner " << i;
  }
  // It looks at the bounds' centre, whatever `direction` says.
  const glm::vec4 centre = f.view_proj * glm::vec4(b.center(), 1.0f);
  EXPECT_NEAR(centre.x / centre.w, 0.0f, 1e-4f);
  EXPECT_NEAR(centre.y / centre.w, 0.0f, 1e-4f);

  l.position = {0.0f, 1.0f, 0.0f};  // inside
  f = scene::shadow_frustum(l, b);
  EXPECT_TRUE(f.six_faces);
  l.position = {5.01f, 1.0f, 0.0f};  // just outside a face: would need ~90 degrees
  f = scene::shadow_frustum(l, b);
  EXPECT_TRUE(f.six_faces);
}

TEST(ShadowFrustum, SpotFrustumReportsItsHalfAngle) {
  const scene::Bounds b = cube(1.0f);
  scene::Light l = light(scene::LightType::spot, {0, 6, 0});
  l.spot_angle = glm::radians(30.0f);
  const scene::ShadowFrustum f = scene::shadow_frustum(l, b);
  EXPECT_NEAR(f.tan_half_fov, std::tan(glm::radians(30.0f)), 1e-5f);
  EXPECT_FALSE(f.six_faces);
}

// A point light's emitter is a sphere: every receiver sees the disk through the centre facing it.
TEST(LightSamples, PointLightDiskFacesTheReceiver) {
  scene::Light l;
  l.type = scene::LightType::point;
  l.position = {0, 3, 0};
  l.size = 0.4f;
  for (const glm::vec3 receiver : {glm::vec3(0, 0, 0), glm::vec3(4, 3, 1), glm::vec3(-1, 7, 2)}) {
    const glm::vec3 facing = glm::normalize(l.position - receiver);
    for (const glm::vec2& d : scene::unit_disk_samples(64, 3)) {
      const glm::vec3 p = scene::point_light_sample(l, d, receiver);
      EXPECT_NEAR(glm::dot(p - l.position, facing), 0.0f, 1e-5f);
      EXPECT_NEAR(glm::length(p - l.position), 0.2f * glm::length(d), 1e-5f);
    }
  }
  l.size = 0.0f;  // a zero-size point light is exactly its position
  EXPECT_EQ(scene::point_light_sample(l, {0.5f, 0.5f}, {1, 1, 1}), l.position);
  EXPECT_STREQ(scene::light_type_name(scene::LightType::point), "point");
}

TEST(BlockerHeightScale, TheScenesHeightAlongTheLightsRays) {
  scene::Bounds b;
  b.extend(glm::vec3(-5, 1, -5));
  b.extend(glm::vec3(5, 3, 5));  // 2 high
  scene::Light l;
  l.direction = glm::normalize(glm::vec3(std::sqrt(3.0f), -1.0f, 0.0f));  // 30 degrees above the horizon
  EXPECT_NEAR(scene::blocker_height_scale(l, b), 4.0f, 1e-5f) << "2 / sin 30";
  l.direction = {0.0f, -1.0f, 0.0f};
  EXPECT_NEAR(scene::blocker_height_scale(l, b), 2.0f, 1e-5f) << "from straight above: the height";
  l.direction = glm::normalize(glm::vec3(1.0f, -0.01f, 0.0f));
  EXPECT_NEAR(scene::blocker_height_scale(l, b), 2.0f / scene::kGrazingRaySine, 1e-3f) << "grazing: bounded";
  l.type = scene::LightType::point;  // the ray to the centre (0, 2, 0) decides, not `direction`
  l.position = {0.0f, 6.0f, 4.0f};   // 45 degrees above it
  EXPECT_NEAR(scene::blocker_height_scale(l, b), 2.0f * std::sqrt(2.0f), 1e-4f);
  EXPECT_EQ(scene::blocker_height_scale(l, scene::Bounds{}), 1.0f) << "no bounds";
}

// The six faces cover every direction: each direction projects inside its own face's tile at
// least kFaceGuardTexels from the tile's edges, and the faces' tiles do not overlap.
TEST(PointLightFaces, EveryDirectionLandsInsideItsFaceTileWithTheGuardBand) {
  const scene::Bounds b = cube(4.0f);
  const scene::Light l = light(scene::LightType::point, {0.5f, -1.0f, 0.3f});
  const int map = 300;
  Result<scene::PointLightFaces> faces = scene::point_light_faces(l, b, map);
  ASSERT_TRUE(faces) << faces.error().to_string();
  EXPECT_EQ(faces->tile, 100);
  float worst = 1e9f;
  for (int i = 0; i < 4000; ++i) {  // a spiral over the sphere, corners of the cube included
    const float z = 1.0f - 2.0f * (i + 0.5f) / 4000.0f, a = 2.39996f * i;
    glm::vec3 d(std::sqrt(1.0f - z * z) * std::cos(a), z, std::sqrt(1.0f - z * z) * std::sin(a));
    if (i < 8) d = glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    const int f = scene::light_face_of(d);
    const scene::LightFace& face = faces->faces[f];
    const glm::vec4 clip = face.view_proj * glm::vec4(l.position + 2.0f * glm::normalize(d), 1.0f);
    ASSERT_GT(clip.w, 0.0f);
    const glm::vec2 texel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * static_cast<float>(face.size);
    worst = std::min({worst, texel.x, texel.y, face.size - texel.x, face.size - texel.y});
    EXPECT_GE(glm::vec2(face.origin).x, 0.0f);
    EXPECT_LE(face.origin.x + face.size, map);
    EXPECT_LE(face.origin.y + face.size, map);
  }
  EXPECT_GE(worst, scene::kFaceGuardTexels - 1e-3f);
  EXPECT_LT(worst, scene::kFaceGuardTexels + 0.5f) << "the guard band is no wider than asked";
  for (int f = 0; f < 6; ++f)
    for (int g = f + 1; g < 6; ++g) EXPECT_NE(faces->faces[f].origin, faces->faces[g].origin);
}

TEST(PointLightFaces, AMapTooSmallForSixFacesIsAnErrorNamingBothSizes) {
  Result<scene::PointLightFaces> faces = scene::point_light_faces(light(scene::LightType::point, {}), {}, 40);
  ASSERT_FALSE(faces);
  EXPECT_NE(faces.error().message.find("48"), std::string::npos) << faces.error().message;
  EXPECT_NE(faces.error().message.find("40"), std::string::npos) << faces.error().message;
}

// The lighting pass's cone: a spot reaches what lies within its half-angle of its axis; the other
// lights reach everything.
TEST(LightReaches, ASpotReachesItsConeOnly) {
  scene::Light spot;
  spot.type = scene::LightType::spot;
  spot.position = glm::vec3(0.0f, 5.0f, 0.0f);
  spot.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  spot.spot_angle = glm::radians(30.0f);
  auto at_degrees = [&](float degrees) {
    const float a = glm::radians(degrees);
    return spot.position + 5.0f * glm::vec3(std::sin(a), -std::cos(a), 0.0f);
  };
  EXPECT_TRUE(scene::light_reaches(spot, at_degrees(0.0f)));
  EXPECT_TRUE(scene::light_reaches(spot, at_degrees(29.0f)));
  EXPECT_FALSE(scene::light_reaches(spot, at_degrees(31.0f)));
  EXPECT_FALSE(scene::light_reaches(spot, spot.position + glm::vec3(0.0f, 1.0f, 0.0f))) << "behind the spot";
  for (scene::LightType other : {scene::LightType::directional, scene::LightType::point}) {
    scene::Light l = spot;
    l.type = other;
    EXPECT_TRUE(scene::light_reaches(l, at_degrees(31.0f)));
    EXPECT_TRUE(scene::light_reaches(l, spot.position + glm::vec3(0.0f, 1.0f, 0.0f)));
  }
}
