#include "sandbox/light_gizmo.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace penumbra::sandbox {

namespace {

// The camera's horizontal frame: forward (up on the disk) and right.
void horizontal_frame(const scene::Camera& camera, glm::vec3& forward, glm::vec3& right) {
  forward = glm::vec3(std::sin(camera.yaw), 0.0f, -std::cos(camera.yaw));
  right = glm::vec3(std::cos(camera.yaw), 0.0f, std::sin(camera.yaw));
}

}  // namespace

glm::vec2 gizmo_point(const glm::vec3& direction, const scene::Camera& camera) {
  glm::vec3 forward, right;
  horizontal_frame(camera, forward, right);
  const glm::vec3 to_light = -glm::normalize(direction);
  const float from_zenith = std::acos(std::clamp(to_light.y, -1.0f, 1.0f));
  const float r = std::min(from_zenith / glm::half_pi<float>(), 1.0f);
  const glm::vec2 horizontal(glm::dot(to_light, right), glm::dot(to_light, forward));
  if (glm::length(horizontal) < 1e-6f) return glm::vec2(0.0f);
  return glm::normalize(horizontal) * r;
}

glm::vec3 gizmo_direction(glm::vec2 p, const scene::Camera& camera) {
  glm::vec3 forward, right;
  horizontal_frame(camera, forward, right);
  const float r = std::min(glm::length(p), 1.0f);
  // Just above the horizon at the rim: a light exactly level lights nothing.
  const float from_zenith = r * glm::radians(89.0f);
  const glm::vec2 d = glm::length(p) > 1e-6f ? glm::normalize(p) : glm::vec2(0.0f, 1.0f);
  const glm::vec3 to_light = std::cos(from_zenith) * glm::vec3(0.0f, 1.0f, 0.0f) +
                             std::sin(from_zenith) * (d.x * right + d.y * forward);
  return -glm::normalize(to_light);
}

}  // namespace penumbra::sandbox
