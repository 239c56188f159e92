// metrics::temporal_change on synthetic frames: a ground plane seen by a panning camera, with
// masks fixed on the surface (stable), fixed on the screen (swimming), flickering in place, and
// a surface uncovered between frames (disocclusion).
#include "metrics/temporal_change.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "scene/camera.h"

namespace penumbra::metrics {
namespace {

constexpr int kW = 96, kH = 64;

// The plane y = 0 seen by `camera`: world positions per pixel (w = 1 where the ray hits it within
// |x| < 4), and a mask from `shade(world position, pixel)`.
SurfaceFrame plane_frame(const scene::Camera& camera, const std::function<float(glm::vec3, glm::ivec2)>& shade) {
  SurfaceFrame f;
  f.view_proj = camera.projection(float(kW) / kH) * camera.view();
  const glm::mat4 inv = glm::inverse(f.view_proj);
  f.mask = MaskImage(kW, kH, 1.0f);
  f.position.assign(size_t{kW} * kH, glm::vec4(0.0f));
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const glm::vec2 ndc((x + 0.5f) / kW * 2.0f - 1.0f, 1.0f - (y + 0.5f) / kH * 2.0f);
      glm::vec4 a = inv * glm::vec4(ndc, -1.0f, 1.0f), b = inv * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 o = glm::vec3(a) / a.w, d = glm::normalize(glm::vec3(b) / b.w - o);
      if (d.y >= 0.0f) continue;
      const glm::vec3 p = o + d * (-o.y / d.y);
      if (std::abs(p.x) > 4.0f) continue;
      f.position[size_t(y) * kW + x] = glm::vec4(p, 1.0f);
      f.mask.at(x, y) = shade(p, {x, y});
    }
  return f;
}

scene::Camera panned(float yaw_degrees) {
  scene::Camera c = scene::Camera::look_at({0.0f, 3.0f, 6.0f}, {0.0f, 0.0f, 0.0f});
  c.yaw += glm::radians(yaw_degrees);
  return c;
}

// A soft shadow edge along world x = 0.3, 0.5 world units wide.
float world_edge(glm::vec3 p, glm::ivec2) { return glm::clamp((p.x - 0.3f) / 0.5f + 0.5f, 0.0f, 1.0f); }

TEST(TemporalChange, AShadowFixedOnTheSurfaceBarelyChangesUnderAPan) {
  std::vector<SurfaceFrame> frames;
  for (int t = 0; t < 4; ++t) frames.push_back(plane_frame(panned(0.5f * t), world_edge));
  auto c = temporal_change(frames);
  ASSERT_TRUE(c) << c.error().to_string();
  EXPECT_GT(c->pixels, size_t{3 * kW * kH / 3});
  EXPECT_LT(c->mean_abs_change, 0.002);  // bilinear resampling of a linear ramp: nearly exact
}

TEST(TemporalChange, AShadowFixedOnTheScreenSwimsByItsSlopeTimesTheMotion) {
  // The same edge, but drawn at a fixed column: it slides over the surface as the camera pans.
  auto screen_edge = [](glm::vec3, glm::ivec2 px) { return glm::clamp((px.x - 40.0f) / 12.0f, 0.0f, 1.0f); };
  std::vector<SurfaceFrame> frames;
  for (int t = 0; t < 4; ++t) frames.push_back(plane_frame(panned(0.5f * t), screen_edge));
  auto stable_frames = std::vector<SurfaceFrame>{};
  for (int t = 0; t < 4; ++t) stable_frames.push_back(plane_frame(panned(0.5f * t), world_edge));
  auto swimming = temporal_change(frames);
  auto stable = temporal_change(stable_frames);
  ASSERT_TRUE(swimming && stable);
  // A 0.5 degree pan moves the image by about 0.5 / 50 * 64 = 0.64 px per frame; the ramp changes
  // by 1/12 per pixel over its 12 columns: 12/96 of the rows' pixels change by about 0.64/12.
  const double expected = (12.0 / kW) * (0.64 / 12.0);
  EXPECT_NEAR(swimming->mean_abs_change, expected, 0.5 * expected);
  EXPECT_GT(swimming->mean_abs_change, 5.0 * stable->mean_abs_change);
}

TEST(TemporalChange, FlickerInPlaceIsItsAmplitude) {
  std::vector<SurfaceFrame> frames;
  for (int t = 0; t < 5; ++t)
    frames.push_back(plane_frame(panned(0.0f), [t](glm::vec3, glm::ivec2) { return t % 2 ? 0.4f : 0.2f; }));
  auto c = temporal_change(frames);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->mean_abs_change, 0.2, 1e-5);
  EXPECT_EQ(c->disoccluded, 0u);
}

TEST(TemporalChange, UncoveredSurfaceIsDisoccludedNotCompared) {
  SurfaceFrame before = plane_frame(panned(0.0f), world_edge);
  SurfaceFrame after = before;
  size_t hidden = 0;
  // In the first frame a blocker (nearer the camera) covered the left quarter: other positions there.
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW / 4; ++x) {
      glm::vec4& p = before.position[size_t(y) * kW + x];
      if (p.w <= 0.0f) continue;
      p = glm::vec4(glm::vec3(p) + glm::vec3(0.0f, 1.0f, 0.0f), 1.0f);
      before.mask.at(x, y) = 0.0f;  // whatever the blocker showed must not count
      ++hidden;
    }
  auto c = temporal_change({before, after});
  ASSERT_TRUE(c);
  EXPECT_GE(c->disoccluded, hidden - kH);  // the quarter's border column may still find a neighbour
  EXPECT_LE(c->disoccluded, hidden);
  EXPECT_LT(c->mean_abs_change, 0.01);
}

TEST(TemporalChange, NeedsTwoFramesOfOneSize) {
  SurfaceFrame a = plane_frame(panned(0.0f), world_edge);
  EXPECT_FALSE(temporal_change({a}));
  SurfaceFrame b = a;
  b.mask = MaskImage(8, 8);
  EXPECT_FALSE(temporal_change({a, b}));
}

}  // namespace
}  // namespace penumbra::metrics
