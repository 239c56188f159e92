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

// A RayScene is a value: changing (or destroying) the scene it was built from afterwards must
// not change what it traces. The texture is made opaque after the build; the hole must stay.
TEST(RaytracedReference, TheBuiltSceneKeepsNoReferenceToItsSource) {
  scene::Scene s = ground_with_blocker(5.0f, 1);
  s.images.push_back({"mask", 2, 2, std::vector<uint8_t>(16, 0)});
  s.materials.push_back({.base_color_texture = 0, .alpha_mode = scene::AlphaMode::mask, .alpha_cutoff = 0.5f});
  Result<reference::RayScene> rs = reference::RayScene::build(s);
  ASSERT_TRUE(rs);
  std::fill(s.images[0].pixels.begin(), s.images[0].pixels.end(), uint8_t{255});
  s.images.clear();
  s.images.shrink_to_fit();
  const std::vector<glm::vec3> pts{{0, 0, 0}}, normals{{0, 1, 0}};
  const metrics::MaskImage v = reference::trace_visibility(*rs, overhead_light(1.0f), pts, normals, 1, 1, {.samples = 64});
  EXPECT_EQ(v.pixels[0], 1.0f);
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

// A zero-size light is one point: the exact hard shadow, binary, the same whatever the number of
// rays asked for (they would all be the same ray).
TEST(RaytracedReference, ZeroSizeLightIsTheExactHardShadow) {
  const scene::Scene s = ground_with_blocker(1.0f);  // 2 x 2 m quad at y = 2
  scene::Light l = overhead_light(0.0f);
  l.type = scene::LightType::spot;  // a point at (0, 10, 0): shadow = quad scaled by 10 / 8
  std::vector<glm::vec3> pts;
  for (int i = 0; i <= 40; ++i) pts.push_back({-2.0f + 0.1f * i, 0.0f, 0.0f});
  Result<reference::RayScene> rs = reference::RayScene::build(s);
  ASSERT_TRUE(rs);
  std::vector<glm::vec3> normals(pts.size(), glm::vec3(0, 1, 0));
  const int n = static_cast<int>(pts.size());
  const metrics::MaskImage one = reference::trace_visibility(*rs, l, pts, normals, n, 1, {.samples = 1});
  const metrics::MaskImage many = reference::trace_visibility(*rs, l, pts, normals, n, 1, {.samples = 256});
  EXPECT_EQ(one.pixels, many.pixels);
  for (int i = 0; i < n; ++i) {
    const float x = std::abs(pts[static_cast<size_t>(i)].x);
    if (std::abs(x - 1.25f) < 1e-3f) continue;  // exactly on the edge
    EXPECT_EQ(one.pixels[static_cast<size_t>(i)], x < 1.25f ? 0.0f : 1.0f) << "x = " << x;
  }
}

// Point lights shine in every direction; a sized one is a sphere whose silhouette disk faces
// each receiver, so its penumbra is symmetric about the light's foot.
TEST(RaytracedReference, PointLightShadowsInEveryDirection) {
  const scene::Scene s = ground_with_blocker(1.0f);
  scene::Light l = overhead_light(0.0f);
  l.type = scene::LightType::point;
  l.direction = {1, 0, 0};  // ignored by a point light
  std::vector<glm::vec3> pts = {{0, 0, 0}, {1.2f, 0, 0}, {-1.2f, 0, 0}, {1.3f, 0, 0}, {-1.3f, 0, 0}, {0, 0, 1.3f}};
  Result<reference::RayScene> rs = reference::RayScene::build(s);
  ASSERT_TRUE(rs);
  std::vector<glm::vec3> normals(pts.size(), glm::vec3(0, 1, 0));
  const int n = static_cast<int>(pts.size());
  metrics::MaskImage v = reference::trace_visibility(*rs, l, pts, normals, n, 1, {.samples = 64});
  EXPECT_EQ(v.pixels[0], 0.0f);
  EXPECT_EQ(v.pixels[1], 0.0f);
  EXPECT_EQ(v.pixels[2], 0.0f);
  EXPECT_EQ(v.pixels[3], 1.0f);
  EXPECT_EQ(v.pixels[4], 1.0f);
  EXPECT_EQ(v.pixels[5], 1.0f);
  l.size = 0.8f;  // penumbra from 1.25 - 0.1 to 1.25 + 0.1 ... wider: (8 / 2) * 0.4 = 0.1 each side x 1.25
  pts = {{1.25f, 0, 0}, {-1.25f, 0, 0}, {0, 0, 1.25f}};
  normals.assign(pts.size(), glm::vec3(0, 1, 0));
  v = reference::trace_visibility(*rs, l, pts, normals, 3, 1, {.samples = 256});
  for (float f : v.pixels) {
    EXPECT_GT(f, 0.3f);
    EXPECT_LT(f, 0.7f);
    EXPECT_NEAR(f, v.pixels[0], 0.02f);  // symmetric
  }
}

// K x K sub-pixel samples box-filter the hard shadow over each pixel: a camera straight down on
// a straight shadow edge sees, in each row, the pixel the edge crosses take the lit fraction of
// its area (to 1/K), and every other pixel stay exactly 0 or 1.
TEST(RaytracedReference, PixelSamplesGiveTheEdgeCoverage) {
  scene::Scene s = ground_with_blocker(0.0f);
  scene::Mesh wall;  // half-plane blocker x < 0.37 at y = 2
  scene::build::add_ground(wall, {-9.63f, 2, 0}, 20, 20);
  s.meshes.push_back(wall);
  s.instances.push_back({1, glm::mat4(1.0f)});
  s.bounds = scene::compute_bounds(s);
  const scene::Light l = overhead_light(0.0f);  // directional straight down: shadow edge at x = 0.37
  scene::Camera cam = scene::Camera::look_at({0, 1, 0}, {0, 0, 0});
  cam.fov_y = glm::radians(20.0f);
  constexpr int w = 32, h = 8;
  // Ground positions of the pixel centres (camera looks down -Y; the ray tracer's primary rays).
  Result<reference::RayScene> rs = reference::RayScene::build(s);
  ASSERT_TRUE(rs);
  std::vector<glm::vec3> pts, normals(w * h, glm::vec3(0, 1, 0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec3 d = reference::camera_ray_direction(cam, w, h, x + 0.5f, y + 0.5f);
      pts.push_back(cam.position + (-cam.position.y / d.y) * d);
    }
  reference::TraceOptions o{.samples = 1};
  o.pixel_samples = 4;
  o.camera = cam;
  // (The blocker is above the camera: the camera only places the sub-pixel samples.)
  const metrics::MaskImage v = reference::trace_visibility(*rs, l, pts, normals, w, h, o);
  // Screen x of the edge: where the pixel-centre ground x crosses 0.37.
  const float px_per_m = w / (pts[w - 1].x - pts[0].x) * (w - 1) / w;
  const float edge_px = 0.5f + (0.37f - pts[0].x) * px_per_m;
  for (int y = 0; y < h; ++y) {
    float lit = 0.0f;
    for (int x = 0; x < w; ++x) {
      const float f = v.at(x, y);
      lit += f;
      if (std::abs(x + 0.5f - edge_px) > 1.0f) {
        EXPECT_TRUE(f == 0.0f || f == 1.0f) << x << "," << y;
      }
    }
    // Lit = the ground at x > 0.37, on whichever side of the edge the screen puts it.
    const float expected = pts[w - 1].x > pts[0].x ? w - edge_px : edge_px;
    EXPECT_NEAR(lit, expected, 0.25f + 1e-3f) << "row " << y;  // 1/K of a pixel
  }
}
