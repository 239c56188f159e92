// Contact hardening on `ball` (sspcss, section 1): the penumbra of the ball's ground shadow
// widens as the ball rises, and follows the ray-traced reference's width.
//
// Probe (from the geometry, as tests/baseline/pcss_contact_hardening_test.cpp does): the light's
// ray through the ball centre meets the ground at the shadow's centre c; the ball scene's light
// comes from +Z, so world X is the shadow ellipse's axis across the light, whose edge is the
// least stretched; the probe runs on the ground from c (umbra) along +X for r + 1 m (lit) and
// measures metrics::penumbra_width (0.02 -> 0.98 rise, pixels) on sspcss's mask and on the
// reference traced from the same G-buffer.
#include <gtest/gtest.h>

#include <cstdio>

#include "metrics/penumbra_width.h"
#include "sspcss_rig.h"

namespace penumbra::test {
namespace {

constexpr int kW = 256, kH = 192;

struct Widths {
  float separable = -1.0f, poisson = -1.0f, reference = -1.0f;  // pixels
};

float width_or_fail(const metrics::MaskImage& mask, glm::vec2 p0, glm::vec2 p1, const std::string& what) {
  Result<float> w = metrics::penumbra_width(mask, p0, p1);
  EXPECT_TRUE(w) << what << ": " << (w ? "" : w.error().to_string());
  return w ? *w : -1.0f;
}

// Both filter variants and the reference on one frame (one G-buffer, one trace).
Widths widths_at(BaselineRenderer& r, float height) {
  scene::Scene s = builtin_scene("ball", {{"ball_height", height}});
  const float radius = 0.5f;  // the scene's default ball_radius, metres
  const glm::vec3 centre(0.0f, height + radius, 0.0f);
  const glm::vec3 c = centre + s.light.direction * ((height + radius) / -s.light.direction.y);
  const glm::vec2 p0 = project_to_pixel(s.camera, c, kW, kH);
  const glm::vec2 p1 = project_to_pixel(s.camera, c + glm::vec3(radius + 1.0f, 0.0f, 0.0f), kW, kH);
  const std::string at = " at ball_height " + std::to_string(height);
  Widths w;
  RenderedFrame f = r.render(s, "sspcss", {}, kW, kH);
  save_for_inspection("ball_separable_h" + std::to_string(height), f.mask);
  w.separable = width_or_fail(f.mask, p0, p1, "separable" + at);
  w.reference = width_or_fail(traced_reference(s, f), p0, p1, "reference" + at);
  RenderedFrame g = r.render(s, "sspcss", {{"filter", "poisson"}}, kW, kH);
  w.poisson = width_or_fail(g.mask, p0, p1, "poisson" + at);
  return w;
}

}  // namespace

TEST(SspcssContactHardening, PenumbraWidensWithTheBallAndFollowsTheReference) {
  BaselineRenderer r;
  const std::vector<float> heights = {0.1f, 0.5f, 1.0f, 1.6f};
  std::vector<Widths> w;
  for (float h : heights) w.push_back(widths_at(r, h));
  for (size_t i = 0; i < heights.size(); ++i)
    std::printf("[ measure  ] ball_height %.1f m: penumbra width separable %.2f px, poisson %.2f px, "
                "reference %.2f px\n", heights[i], w[i].separable, w[i].poisson, w[i].reference);
  for (size_t i = 1; i < w.size(); ++i) {
    const std::string step = "ball_height " + std::to_string(heights[i - 1]) + " -> " + std::to_string(heights[i]);
    EXPECT_GT(w[i].separable, w[i - 1].separable) << step;
    EXPECT_GT(w[i].poisson, w[i - 1].poisson) << step;
    EXPECT_GT(w[i].reference, w[i - 1].reference) << "the reference itself, " << step;
  }
  // Measured (OSMesa, 256x192, 2048^2 map), ball_height 0.1 / 0.5 / 1.0 / 1.6 m:
  //   separable 3.66 / 4.96 / 6.23 / 8.03 px, poisson 3.87 / 5.01 / 6.48 / 8.45 px,
  //   reference 3.29 / 3.92 / 5.44 / 7.03 px: ratios 1.11-1.27 and 1.18-1.28. sspcss is a little
  //   wider: the anti-aliased hard shadow adds a fraction of a pixel, and the separable Gaussian's
  //   tails (sigma = W / 4, the variance of the disk) reach 0.02 and 0.98 further out than the
  //   disk light's profile does.
  // Bound: within [0.75, 1.4] x the reference at every height; a fixed kernel (PCF: 2.1-2.6 px
  // at every height) misses it from 0.5 m on.
  for (size_t i = 0; i < w.size(); ++i) {
    for (float v : {w[i].separable, w[i].poisson}) {
      EXPECT_GT(v, 0.75f * w[i].reference) << "ball_height " << heights[i];
      EXPECT_LT(v, 1.4f * w[i].reference) << "ball_height " << heights[i];
    }
  }
}

}  // namespace penumbra::test
