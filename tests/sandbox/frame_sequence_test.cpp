// Frame sequences' poses and specs (GL-free).
#include <gtest/gtest.h>

#include <filesystem>

#include "sandbox/frame_sequence.h"

namespace penumbra::sandbox {
namespace {

TEST(FrameSequence, AnOrbitKeepsTheSceneCentreWhereTheCameraSeesIt) {
  scene::Camera cam;
  cam.position = {3.0f, 2.0f, 5.0f};
  cam.yaw = 0.3f;
  cam.pitch = -0.2f;
  const glm::vec3 centre(1.0f, 0.0f, -1.0f);
  const glm::vec3 to_centre = centre - cam.position;
  for (float deg : {30.0f, 90.0f, 200.0f}) {
    const scene::Camera o = orbited(cam, centre, deg);
    const glm::vec3 now = centre - o.position;
    EXPECT_NEAR(glm::length(now), glm::length(to_centre), 1e-4f) << deg;
    EXPECT_NEAR(o.position.y, cam.position.y, 1e-5f) << deg;
    // Same angle between the view direction and the centre: the scene turns in front of the camera.
    EXPECT_NEAR(glm::dot(glm::normalize(now), o.forward()), glm::dot(glm::normalize(to_centre), cam.forward()), 1e-4f) << deg;
  }
  const scene::Camera full = orbited(cam, centre, 360.0f);
  EXPECT_NEAR(glm::distance(full.position, cam.position), 0.0f, 1e-4f);
  EXPECT_NEAR(glm::distance(full.forward(), cam.forward()), 0.0f, 1e-4f);
}

TEST(FrameSequence, TurningTheLightHalfWayReversesItsHorizontalDirection) {
  scene::Light l;
  l.direction = glm::normalize(glm::vec3(1.0f, -2.0f, 0.5f));
  l.position = {-2.0f, 8.0f, -1.0f};
  const scene::Light t = turned(l, glm::vec3(0.0f), 180.0f);
  EXPECT_NEAR(t.direction.x, -l.direction.x, 1e-5f);
  EXPECT_NEAR(t.direction.z, -l.direction.z, 1e-5f);
  EXPECT_NEAR(t.direction.y, l.direction.y, 1e-6f);
  EXPECT_NEAR(t.position.x, 2.0f, 1e-5f);
}

TEST(FrameSequence, SpecsAreCheckedAndFramesNumbered) {
  SequenceSpec s;
  s.dir = std::filesystem::temp_directory_path().string();
  EXPECT_TRUE(check_sequence(s));
  EXPECT_EQ(std::filesystem::path(sequence_frame_path(s, 7)).filename(), "frame_0007.png");
  SequenceSpec bad = s;
  bad.frames = 0;
  EXPECT_FALSE(check_sequence(bad));
  bad = s;
  bad.degrees = 1e6f;
  EXPECT_FALSE(check_sequence(bad));
  bad = s;
  bad.dir = s.dir + "/no/such/folder";
  EXPECT_NE(check_sequence(bad).error().message.find("does not exist"), std::string::npos);
  EXPECT_FALSE(parse_sequence_path("spiral"));
  EXPECT_EQ(*parse_sequence_path("light"), SequenceSpec::Path::light);
}

}  // namespace
}  // namespace penumbra::sandbox
