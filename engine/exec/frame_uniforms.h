#pragma once
// The camera every pass can read without binding anything: the executor fills one uniform
// buffer per frame and binds it at kFrameUniformBinding. The GLSL side is
// engine/gl/shaders/frame_uniforms.glsl (std140; the member order below is its order), which
// passes/gbuffer/gbuffer_read.glsl uses to rebuild positions from the G-buffer's view depth.
#include <glm/glm.hpp>

#include "exec/frame_inputs.h"
#include "gl/buffer.h"

namespace penumbra::exec {

inline constexpr unsigned kFrameUniformBinding = 0;

struct FrameUniforms {
  glm::mat4 view;
  glm::mat4 inverse_view;
  glm::mat4 projection;
  glm::mat4 inverse_projection;
  glm::vec4 camera_position;  // w = 1
  glm::ivec4 screen;          // width, height, 0, 0 (pixels)
  glm::vec4 ray00;            // exec::PixelRays at the screen size (xyz; w = 0)
  glm::vec4 ray_dx;
  glm::vec4 ray_dy;
};
static_assert(sizeof(FrameUniforms) == 4 * 64 + 5 * 16, "std140 layout of FrameUniforms");

FrameUniforms frame_uniforms(const FrameInputs& frame);

// Uploads `frame`'s uniforms into `buffer` (created on first use) and binds it.
void bind_frame_uniforms(gl::Buffer& buffer, const FrameInputs& frame);

}  // namespace penumbra::exec
