#pragma once
// Perspective camera stored as the data the sandbox drives (position, yaw, pitch), from which
// view and projection matrices are derived. Angles in radians, distances in world units.
// yaw = 0, pitch = 0 looks along -Z; positive yaw turns towards +X; positive pitch looks up.
//
//   Camera cam = Camera::look_at({0, 2, 5}, {0, 0, 0});
//   glm::mat4 view_proj = cam.projection(16.0f / 9.0f) * cam.view();
#include <glm/glm.hpp>

namespace penumbra::scene {

struct Camera {
  glm::vec3 position{0.0f, 1.0f, 5.0f};
  float yaw = 0.0f;                      // radians
  float pitch = 0.0f;                    // radians, clamped to (-pi/2, pi/2) by look_at
  float fov_y = glm::radians(50.0f);     // vertical field of view, radians
  float near_plane = 0.05f;              // world units
  float far_plane = 200.0f;              // world units

  static Camera look_at(const glm::vec3& eye, const glm::vec3& target,
                        float fov_y = glm::radians(50.0f), float near_plane = 0.05f,
                        float far_plane = 200.0f);

  glm::vec3 forward() const;  // unit view direction
  glm::mat4 view() const;     // world -> eye (right-handed, looking down -Z)
  // OpenGL clip convention (z in [-1, 1]); aspect = width / height.
  glm::mat4 projection(float aspect) const;
};

}  // namespace penumbra::scene
