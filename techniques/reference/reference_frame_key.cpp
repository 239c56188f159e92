#include "reference_frame_key.h"

#include "exec/gpu_scene.h"

namespace penumbra::reference {

ReferenceFrameKey make_frame_key(const exec::FrameInputs& frame, std::vector<double> settings) {
  ReferenceFrameKey k;
  k.scene = frame.scene ? frame.scene->serial() : 0;
  const scene::Camera& c = frame.camera;
  k.camera_position = c.position;
  k.camera_yaw = c.yaw;
  k.camera_pitch = c.pitch;
  k.camera_fov_y = c.fov_y;
  k.camera_near = c.near_plane;
  k.camera_far = c.far_plane;
  const scene::Light& l = frame.light;
  k.light_type = static_cast<int>(l.type);
  k.light_position = l.position;
  k.light_direction = l.direction;
  k.light_size = l.size;
  k.light_spot_angle = l.spot_angle;
  k.screen_w = frame.screen_w;
  k.screen_h = frame.screen_h;
  k.settings = std::move(settings);
  return k;
}

}  // namespace penumbra::reference
