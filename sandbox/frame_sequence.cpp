#include "sandbox/frame_sequence.h"

#include "util/file_read.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace penumbra::sandbox {

namespace {

// Turns (x, z) by `a` radians about +y the way increasing Camera::yaw turns forward().
glm::vec3 turned_about_y(const glm::vec3& v, float a) {
  const float c = std::cos(a), s = std::sin(a);
  return {v.x * c - v.z * s, v.y, v.z * c + v.x * s};
}

}  // namespace

Result<SequenceSpec::Path> parse_sequence_path(const std::string& name) {
  if (name == "orbit") return SequenceSpec::Path::orbit;
  if (name == "light") return SequenceSpec::Path::light;
  return make_error("the sequence's path must be \"orbit\" (the camera) or \"light\", got \"" + name + "\"");
}

Status check_sequence(const SequenceSpec& spec) {
  if (spec.frames < 1 || spec.frames > kMaxSequenceFrames)
    return make_error("a sequence has 1.." + std::to_string(kMaxSequenceFrames) + " frames, got " + std::to_string(spec.frames));
  if (!std::isfinite(spec.degrees) || std::abs(spec.degrees) > 3600.0f)
    return make_error("a sequence turns by -3600..3600 degrees, got " + std::to_string(spec.degrees));
  if (spec.dir.empty()) return make_error("a sequence needs a folder to write into");
  if (Status d = check_directory(spec.dir); !d)
    return make_error("the sequence's folder '" + shortened(spec.dir) + "' " + d.error().message);
  return {};
}

scene::Camera orbited(scene::Camera camera, const glm::vec3& centre, float degrees) {
  const float a = glm::radians(degrees);
  camera.position = centre + turned_about_y(camera.position - centre, a);
  camera.yaw += a;
  return camera;
}

scene::Light turned(scene::Light light, const glm::vec3& centre, float degrees) {
  const float a = glm::radians(degrees);
  light.direction = turned_about_y(light.direction, a);
  light.position = centre + turned_about_y(light.position - centre, a);
  return light;
}

std::string sequence_frame_path(const SequenceSpec& spec, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", index);
  return (std::filesystem::path(spec.dir) / name).string();
}

}  // namespace penumbra::sandbox
