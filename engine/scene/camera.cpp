#include "scene/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::scene {

Camera Camera::look_at(const glm::vec3& eye, const glm::vec3& target, float fov_y,
                       float near_plane, float far_plane) {
  Camera c;
  c.position = eye;
  glm::vec3 d = target - eye;
  d = glm::length(d) > 0.0f ? glm::normalize(d) : glm::vec3(0.0f, 0.0f, -1.0f);
  c.yaw = std::atan2(d.x, -d.z);
  // Stay just short of straight up/down so view() keeps a well-defined up vector.
  c.pitch = std::clamp(std::asin(std::clamp(d.y, -1.0f, 1.0f)), -1.5607f, 1.5607f);
  c.fov_y = fov_y;
  c.near_plane = near_plane;
  c.far_plane = far_plane;
  return c;
}

glm::vec3 Camera::forward() const {
  return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}

glm::mat4 Camera::view() const {
  return glm::lookAt(position, position + forward(), glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspective(fov_y, aspect, near_plane, far_plane);
}

}  // namespace penumbra::scene
