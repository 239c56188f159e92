#include <gtest/gtest.h>

#include "metrics/penumbra_width.h"
#include "raytraced_reference.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

using namespace penumbra;

namespace {

scene::Light overhead_light(float size) {
  scene::Light l;
  l.direction = {0, -1, 0};
  l.position = {0, 10, 0};
  l.size = size;
  return l;
}

// Ground receiver point(s) at the origin, normal up.
metrics::MaskImage trace_points(const scene::Scene& s, const scene::Light& l, std::vector<glm::vec3> pts) {
  Result<reference::RayScene> rs = reference::RayScene::build(s);
  EXPECT_TRUE(rs);
  std::vector<glm::vec3> normals(pts.size(), glm::vec3(0, 1, 0));
  return reference::trace_visibility(*rs, l, pts, normals, static_cast<int>(pts.size()), 1, {.samples = 64});
}

scene::Scene ground_with_blocker(float half_width, uint32_t blocker_material = 0) {
  scene::Scene s;
  s.materials.push_back({});
  scene::Mesh ground;
  scene::build::add_ground(ground, {0, 0, 0}, 40, 40);
  s.meshes.push_back(ground);
  s.instances.push_back({0, glm::mat4(1.0f)});
  if (half_width > 0.0f) {
    scene::Mesh quad;  // horizontal quad at y = 2, UVs spanning [0,1]
    scene::build::add_ground(quad, {0, 2, 0}, 2 * half_width, 2 * half_width);
    quad.material = blocker_material;
    s.meshes.push_back(quad);
    s.instances.push_back({1, glm::mat4(1.0f)});
  }
  s.bounds = scene::compute_bounds(s);
  return s;
}

}  // namespace

TEST(RaytracedReference, FullyLitReceiverIsExactlyOne) {
  const metrics::MaskImage v = trace_points(ground_with_blocker(0.0f), overhead_light(1.0f), {{0, 0, 0}, {3, 0, -2}});
  EXPECT_EQ(v.pixels[0], 1.0f);
  EXPECT_EQ(v.pixels[1], 1.0f);
}

TEST(RaytracedReference, WideBlockerGivesUmbraUnderItsCentre) {
  const metrics::MaskImage v = trace_points(ground_with_blocker(5.0f), overhead_light(1.0f), {{0, 0, 0}, {15, 0, 0}});
  EXPECT_EQ(v.pixels[0], 0.0f);
  EXPECT_EQ(v.pixels[1], 1.0f);  // far outside the blocker's shadow
}

TEST(RaytracedReference, AlphaMaskedQuadCastsOnlyWhereOpaque) {
  for (uint8_t alpha : {uint8_t{0}, uint8_t{255}}) {
    scene::Scene s = ground_with_blocker(5.0f, 1);
    scene::Image img{"mask", 2, 2, std::vector<uint8_t>(16, 255)};
    for (int i = 0; i < 4; ++i) img.pixels[static_cast<size_t>(i) * 4 + 3] = alpha;
    s.images.push_back(img);
    s.materials.push_back({.base_color_texture = 0, .alpha_mode = scene::AlphaMode::mask, .alpha_cutoff = 0.5f});
    const metrics::MaskImage v = trace_points(s, overhead_light(1.0f), {{0, 0, 0}});
    EXPECT_EQ(v.pixels[0], alpha == 0 ? 1.0f : 0.0f) << "alpha " << int(alpha);
  }
}

// Physics sanity: the lateral penumbra of the ball's shadow widens as the ball rises.
static float ball_penumbra_width(float ball_height) {
  Result<scene::Scene> s = scene::make_builtin_scene("ball", {{"ball_height", ball_height}});
  EXPECT_TRUE(s);
  const scene::Light& l = s->light;
  const glm::vec3 centre(0.0f, ball_height + 0.5f, 0.0f);
  // A directional light is a sun (scene/light.h): the shadow's centre line is the ball
  // projected along the light direction onto y = 0, and the probe runs sideways from there.
  const glm::vec3 ray = glm::normalize(l.direction);
  const glm::vec3 shadow_centre = centre + ray * (-centre.y / ray.y);
  const glm::vec3 lateral = glm::normalize(glm::cross(ray, glm::vec3(0, 1, 0)));
  constexpr int n = 96;
  constexpr float probe_length = 1.2f, step = probe_length / (n - 1);  // metres
  std::vector<glm::vec3> pts;
  for (int i = 0; i < n; ++i) pts.push_back(shadow_centre + lateral * (step * static_cast<float>(i)));
  const metrics::MaskImage v = trace_points(*s, l, pts);
  EXPECT_EQ(v.pixels.front(), 0.0f);  // umbra at the shadow's centre line
  EXPECT_EQ(v.pixels.back(), 1.0f);   // lit beyond its edge
  Result<float> w = metrics::penumbra_width(v, {0.5f, 0.5f}, {n - 0.5f, 0.5f});
  EXPECT_TRUE(w) << (w ? "" : w.error().to_string());
  return w ? *w * step : -1.0f;  // metres
}

TEST(RaytracedReference, BallPenumbraGrowsWithHeight) {
  const float low = ball_penumbra_width(0.1f), high = ball_penumbra_width(1.0f);
  EXPECT_GT(low, 0.0f);
  EXPECT_GT(high, 1.5f * low) << "low " << low << " m, high " << high << " m";
}

TEST(RaytracedReference, PrimaryGBufferSeesTheGround) {
  scene::Scene s = ground_with_blocker(0.0f);
  Result<reference::RayScene> rs = reference::RayScene::build(s);
  ASSERT_TRUE(rs);
  const auto cam = scene::Camera::look_at({0, 5, 5}, {0, 0, 0});
  reference::GBuffer g = reference::primary_gbuffer(*rs, cam, 32, 32);
  const size_t centre = 16 * 32 + 16;
  ASSERT_EQ(g.coverage[centre], 1);
  EXPECT_NEAR(g.positions[centre].y, 0.0f, 1e-4f);
  EXPECT_NEAR(g.normals[centre].y, 1.0f, 1e-5f);
  std::vector<float> progress;
  metrics::MaskImage v = reference::trace_visibility(*rs, overhead_light(1.0f), g,
                                                     {.samples = 4, .progress = [&](float f) { progress.push_back(f); }});
  ASSERT_FALSE(progress.empty());
  EXPECT_EQ(progress.back(), 1.0f);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_EQ(v.pixels[centre], 1.0f);
}
