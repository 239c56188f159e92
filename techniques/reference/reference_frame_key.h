#pragma once
// The reset rule of both references: an accumulated (raster) or traced (ray-traced) result stays
// valid while everything it depends on is unchanged since the frame it was made from: the scene,
// the camera, the light's geometry, the screen size and the method's own settings.
//
//   ReferenceFrameKey key = make_frame_key(ctx.frame(), {samples, map_size, seed});
//   if (key != last_key_) { reset(); last_key_ = key; }
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "exec/frame_inputs.h"

namespace penumbra::reference {

struct ReferenceFrameKey {
  // The GpuScene pointer alone could be reused by a new scene allocated at the same address, so
  // the triangle count and bounds go with it (a scene parameter such as ball_height moves them).
  const void* scene = nullptr;
  std::size_t triangles = 0;
  glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};
  glm::vec3 camera_position{0.0f};
  float camera_yaw = 0, camera_pitch = 0, camera_fov_y = 0, camera_near = 0, camera_far = 0;
  int light_type = 0;
  glm::vec3 light_position{0.0f}, light_direction{0.0f};
  float light_size = 0, light_spot_angle = 0;
  int screen_w = 0, screen_h = 0;
  std::vector<double> settings;  // the method's parameters that change the result

  bool operator==(const ReferenceFrameKey&) const = default;
};

ReferenceFrameKey make_frame_key(const exec::FrameInputs& frame, std::vector<double> settings);

}  // namespace penumbra::reference
