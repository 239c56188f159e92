// `penumbra eval --flicker-step Npx`: the turn per frame that moves the image centre by N pixels,
// so that --flicker-match finds a wide band of pixels landing on pixel centres.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "measurement/flicker_run.h"

using namespace penumbra;

namespace {

// Pixels from the image centre at which the centre ray of `turned` lands in `start`'s view.
glm::vec2 centre_in(const scene::Camera& start, const scene::Camera& turned, int w, int h) {
  const glm::vec4 clip = start.projection(float(w) / float(h)) * start.view() * glm::vec4(turned.position + turned.forward(), 1.0f);
  return 0.5f * glm::vec2(clip) / clip.w * glm::vec2(w, h);
}

}  // namespace

TEST(PanStep, EveryStepMovesTheImageCentreByTheGivenPixels) {
  // Pitched down as the built-in views are: the turn is about the world's vertical, not the view's.
  const scene::Camera start = scene::Camera::look_at({0.0f, 3.0f, 8.0f}, {1.0f, 0.0f, 0.0f}, glm::radians(50.0f));
  for (float pixels : {0.5f, 1.0f, 3.0f}) {
    auto degrees = measurement::pan_degrees_for_pixels(start, 480, 270, pixels);
    ASSERT_TRUE(degrees) << degrees.error().message;
    EXPECT_GT(*degrees, 0.0f);
    scene::Camera previous = start;
    for (int step = 1; step <= 4; ++step) {
      scene::Camera next = start;
      next.yaw += glm::radians(*degrees) * float(step);
      const glm::vec2 shift = centre_in(previous, next, 480, 270);
      EXPECT_NEAR(glm::length(shift), pixels, 1e-3f) << pixels << " px, step " << step;
      EXPECT_NEAR(shift.y, 0.0f, 0.01f);  // --flicker-match's tolerance: the band lands on centres
      previous = next;
    }
  }
  // Twice the pixels on a twice as tall image: the same turn.
  auto small = measurement::pan_degrees_for_pixels(start, 480, 270, 1.0f);
  auto large = measurement::pan_degrees_for_pixels(start, 960, 540, 2.0f);
  ASSERT_TRUE(small && large);
  EXPECT_NEAR(*small, *large, 1e-4f);
}

TEST(PanStep, AStepBeyondTheViewIsAnError) {
  const scene::Camera start = scene::Camera::look_at({0.0f, 3.0f, 8.0f}, {0.0f, 0.0f, 0.0f}, glm::radians(50.0f));
  auto far = measurement::pan_degrees_for_pixels(start, 480, 270, 5000.0f);
  ASSERT_FALSE(far);
  EXPECT_NE(far.error().message.find("out of the view"), std::string::npos) << far.error().message;
  EXPECT_FALSE(measurement::pan_degrees_for_pixels(start, 480, 270, 0.0f));
}
