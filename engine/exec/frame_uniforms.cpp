#include "exec/frame_uniforms.h"

#include "exec/gbuffer_readback.h"

namespace penumbra::exec {

FrameUniforms frame_uniforms(const FrameInputs& frame) {
  FrameUniforms u{};
  u.view = frame.view();
  u.inverse_view = glm::inverse(u.view);
  u.projection = frame.projection();
  u.inverse_projection = glm::inverse(u.projection);
  u.camera_position = glm::vec4(frame.camera.position, 1.0f);
  u.screen = glm::ivec4(frame.screen_w, frame.screen_h, 0, 0);
  const PixelRays rays = pixel_rays(u.view, u.projection, frame.screen_w, frame.screen_h);
  u.ray00 = glm::vec4(rays.ray00, 0.0f);
  u.ray_dx = glm::vec4(rays.ray_dx, 0.0f);
  u.ray_dy = glm::vec4(rays.ray_dy, 0.0f);
  return u;
}

void bind_frame_uniforms(gl::Buffer& buffer, const FrameInputs& frame) {
  const FrameUniforms u = frame_uniforms(frame);
  if (buffer.size() != sizeof u) buffer = gl::Buffer(sizeof u, &u, /*dynamic=*/true);
  else buffer.update(&u, sizeof u);
  buffer.bind_base(GL_UNIFORM_BUFFER, kFrameUniformBinding);
}

}  // namespace penumbra::exec
