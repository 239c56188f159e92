#include "exec/frame_uniforms.h"

namespace penumbra::exec {

FrameUniforms frame_uniforms(const FrameInputs& frame) {
  FrameUniforms u{};
  u.view = frame.view();
  u.inverse_view = glm::inverse(u.view);
  u.projection = frame.projection();
  u.inverse_projection = glm::inverse(u.projection);
  u.camera_position = glm::vec4(frame.camera.position, 1.0f);
  u.screen = glm::ivec4(frame.screen_w, frame.screen_h, 0, 0);
  return u;
}

void bind_frame_uniforms(gl::Buffer& buffer, const FrameInputs& frame) {
  const FrameUniforms u = frame_uniforms(frame);
  if (buffer.size() != sizeof u) buffer = gl::Buffer(sizeof u, &u, /*dynamic=*/true);
  else buffer.update(&u, sizeof u);
  buffer.bind_base(GL_UNIFORM_BUFFER, kFrameUniformBinding);
}

}  // namespace penumbra::exec
