// PCSS contact hardening (Fernando 2005, eq. 1): the penumbra widens with the blocker-receiver
// distance. On `ball` we raise the ball and measure the width of its shadow's edge.
//
// Probe (chosen from the geometry, not from the image): the directional light's ray through
// the ball centre meets the ground (y = 0) at the shadow's centre c = centre + dir * t,
// t = (ball_height + r) / -dir.y. An orthographic projection of a sphere of radius r along
// `dir` is an ellipse whose semi-axis perpendicular to the light's horizontal direction is
// exactly r; the ball scene's light comes from +Z (azimuth 0), so that axis is world X. The
// probe runs on the ground from c (umbra) along +X to c + (r + 1.0 m) X (lit), crossing the
// shadow's side edge once; both ends are projected with the scene camera. The width is
// metrics::penumbra_width (0.02 -> 0.98 rise, pixels), measured the same way on the ray-traced
// reference of the same G-buffer (Embree, 256 light samples).
#include <gtest/gtest.h>

#include "baseline_frame.h"
#include "metrics/penumbra_width.h"
#include "raytraced_reference.h"
#include "test_support/inspection.h"

namespace penumbra::test {
namespace {

constexpr int kW = 256, kH = 192;

struct Widths {
  float technique = -1.0f;  // pixels
  float reference = -1.0f;  // the ray-traced reference on the same G-buffer, same probe
};

Widths measured_widths(BaselineRenderer& r, const std::string& technique, float height, bool with_reference) {
  scene::Scene s = builtin_scene("ball", {{"ball_height", height}});
  const float radius = 0.5f;  // the scene's default ball_radius, metres
  const glm::vec3 centre(0.0f, height + radius, 0.0f);
  const glm::vec3 dir = s.light.direction;
  const glm::vec3 c = centre + dir * ((height + radius) / -dir.y);
  const glm::vec2 p0 = project_to_pixel(s.camera, c, kW, kH);
  const glm::vec2 p1 = project_to_pixel(s.camera, c + glm::vec3(radius + 1.0f, 0.0f, 0.0f), kW, kH);
  RenderedFrame f = r.render(s, technique, {}, kW, kH);
  save_for_inspection("ball_" + technique + "_h" + std::to_string(height), f.mask);
  Widths out;
  Result<float> w = metrics::penumbra_width(f.mask, p0, p1);
  EXPECT_TRUE(w) << technique << " at ball_height " << height << ": " << (w ? "" : w.error().to_string());
  if (w) out.technique = *w;
  if (with_reference) {
    Result<reference::RayScene> rs = reference::RayScene::build(s);
    EXPECT_TRUE(rs);
    if (!rs) return out;
    metrics::MaskImage ref =
        reference::trace_visibility(*rs, s.light, f.positions, f.normals, kW, kH, {.samples = 256}, f.coverage);
    Result<float> rw = metrics::penumbra_width(ref, p0, p1);
    EXPECT_TRUE(rw) << "reference at ball_height " << height;
    if (rw) out.reference = *rw;
  }
  return out;
}

TEST(PcssContactHardening, PenumbraWidthGrowsWithBallHeight) {
  BaselineRenderer r;
  const std::vector<float> heights = {0.1f, 0.5f, 1.0f, 1.6f};
  std::vector<Widths> widths;
  for (float h : heights) widths.push_back(measured_widths(r, "pcss", h, true));
  for (size_t i = 0; i < heights.size(); ++i)
    std::printf("ball_height %.2f m: penumbra width pcss %.2f px, reference %.2f px\n", heights[i],
                widths[i].technique, widths[i].reference);
  for (size_t i = 1; i < widths.size(); ++i) {
    EXPECT_GT(widths[i].technique, widths[i - 1].technique) << "ball_height " << heights[i - 1] << " -> " << heights[i];
    EXPECT_GT(widths[i].reference, widths[i - 1].reference) << "the reference itself";
  }
  // PCSS follows the reference's widths. Measured (OSMesa, 256x192, shadow map 2048):
  //   ball_height 0.1 / 0.5 / 1.0 / 1.6 m: pcss 3.65 / 4.14 / 5.66 / 6.92 px,
  //   reference 3.29 / 3.92 / 5.44 / 7.03 px: ratios 1.11 / 1.06 / 1.04 / 0.98.
  // Bound: ratio in [0.8, 1.25]; PCF's fixed 2.1-2.6 px fails it above 0.1 m.
  for (const Widths& w : widths) {
    EXPECT_GT(w.technique, 0.8f * w.reference);
    EXPECT_LT(w.technique, 1.25f * w.reference);
  }
}

// Contrast: PCF's penumbra is a fixed kernel in texels, so it barely changes with height.
TEST(PcssContactHardening, PcfWidthDoesNotFollowHeight) {
  BaselineRenderer r;
  const float low = measured_widths(r, "pcf", 0.1f, false).technique;
  const float high = measured_widths(r, "pcf", 1.6f, false).technique;
  std::printf("pcf ball_height 0.1 m: %.2f px, 1.6 m: %.2f px\n", low, high);
  EXPECT_LT(std::abs(high - low), 1.5f);
}

}  // namespace
}  // namespace penumbra::test
