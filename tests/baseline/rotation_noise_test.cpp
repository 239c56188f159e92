// rotation_noise (passes/sampling/rotation_noise.h): with the default `surface` key a receiver's
// tap rotation belongs to its place in the shadow map, so a camera move leaves the mask of a
// surface point as it was; the papers' `screen` key gives it a new rotation. A top-down view of
// `ball`'s ground moved sideways by exactly three pixels maps every ground pixel onto a pixel of
// the first frame, with no resampling.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "test_support/technique_rig.h"
#include "techniques/builtin_techniques.h"

using namespace penumbra;

namespace {

constexpr int kW = 192, kH = 144;
constexpr float kShiftPixels = 3.0f;

struct Change {
  double mean = 0.0;  // mean |mask after - mask before| over the matched soft-penumbra pixels
  int pixels = 0;
};

// The mean change of `technique`'s mask at the same ground points between a top-down view and the
// same view moved sideways by kShiftPixels.
Change ground_change(const std::string& technique, const std::vector<std::string>& settings) {
  const scene::Scene s = test::builtin_scene("ball");
  test::TechniqueRig rig({.width = kW, .height = kH, .shadow_size = 1024, .techniques = register_builtin_techniques});
  // Nearly straight down (a look_at straight down has no yaw), the ground fills the view.
  const scene::Camera above = scene::Camera::look_at({0.4f, 5.0f, 0.401f}, {0.4f, 0.0f, 0.4f}, glm::radians(50.0f));
  const glm::vec3 centre(0.4f, 0.0f, 0.4f);
  const glm::vec3 right = glm::normalize(glm::cross(above.forward(), glm::vec3(0.0f, 1.0f, 0.0f)));
  // Pixels per world unit on the ground: the camera moved by a unit shifts the image by this.
  scene::Camera probe = above;
  probe.position += right;
  const float per_unit = glm::length(test::project_to_pixel(above, centre, kW, kH) - test::project_to_pixel(probe, centre, kW, kH));
  scene::Camera moved = above;
  moved.position += right * (kShiftPixels / per_unit);

  rig.set_scene(s);
  rig.use(technique);
  rig.set(settings);
  rig.session().camera() = above;
  rig.render(2);
  const metrics::MaskImage before = rig.shadow_mask();
  rig.session().camera() = moved;
  rig.render(2);
  const metrics::MaskImage after = rig.shadow_mask();
  const std::vector<glm::vec4> positions = rig.positions();

  Change c;
  double sum = 0.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const glm::vec4 p = positions[static_cast<size_t>(y) * kW + x];
      if (p.w <= 0.0f || std::abs(p.y) > 1e-3f) continue;  // the ground only: the shift is exact there
      const float v = after.at(x, y);
      if (v <= 0.02f || v >= 0.98f) continue;
      const glm::vec2 at = test::project_to_pixel(above, glm::vec3(p), kW, kH) - 0.5f;
      const glm::ivec2 q(glm::round(at));
      if (glm::length(at - glm::vec2(q)) > 0.02f || q.x < 0 || q.y < 0 || q.x >= kW || q.y >= kH) continue;
      sum += std::abs(v - before.at(q.x, q.y));
      ++c.pixels;
    }
  c.mean = c.pixels ? sum / c.pixels : 0.0;
  return c;
}

}  // namespace

TEST(TapRotation, SurfaceKeyedRotationsStayWithTheSurfaceWhenTheCameraMoves) {
  for (const char* t : {"pcss", "pcf", "pmchss"}) {
    std::vector<std::string> extra;
    if (std::string(t) == "pcf") extra = {"kernel=vogel", "radius=6"};
    if (std::string(t) == "pmchss") extra = {"variant=regular"};  // the mask variant's mask lies on the screen
    std::vector<std::string> surface = extra, screen = extra;
    screen.push_back("rotation_noise=screen");
    const Change steady = ground_change(t, surface), swimming = ground_change(t, screen);
    std::printf("[ measure  ] %s: change at the same ground points after a %.0f px move: surface %.5f (%d px), "
                "screen %.5f (%d px)\n", t, kShiftPixels, steady.mean, steady.pixels, swimming.mean, swimming.pixels);
    ASSERT_GT(steady.pixels, 200) << t << ": the ball's penumbra must lie on the matched ground";
    ASSERT_GT(swimming.pixels, 200) << t;
    // Measured: surface 0.003, screen 0.031-0.033. What is left on the surface: points up to
    // 0.02 px apart (the G-buffer's depth precision) cross a noise cell or a texel now and then.
    EXPECT_LT(steady.mean, 0.006) << t << ": the same taps at the same surface point";
    EXPECT_GT(swimming.mean, 5.0 * steady.mean + 0.005) << t << ": screen noise rotates them anew";
  }
}
