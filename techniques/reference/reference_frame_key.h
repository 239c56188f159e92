#pragma once
// The reset rule of both references: an accumulated (raster) or traced (ray-traced) result stays
// valid while everything it depends on is unchanged since the frame it was made from: the scene,
// the camera, the light's geometry, the screen size and the method's own settings.
//
//   ReferenceFrameKey key = make_frame_key(ctx.frame(), {samples, map_size, seed});
//   if (key != last_key_) { reset(); last_key_ = key; }
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "exec/frame_inputs.h"

namespace penumbra::reference {

struct ReferenceFrameKey {
  // GpuScene::serial(), not its address: a new scene allocated where the last one was, with the
  // same triangles and bounds and another texture, is another scene. 0: none.
  std::uint64_t scene = 0;
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
