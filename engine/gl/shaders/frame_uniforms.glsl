// The frame's camera, bound by the executor for every pass (exec/frame_uniforms.h holds the C++
// side of this block; keep the two in the same order).
layout(std140, binding = 0) uniform FrameUniforms {
  mat4 frame_view;
  mat4 frame_inverse_view;
  mat4 frame_projection;
  mat4 frame_inverse_projection;
  vec4 frame_camera_position;
  ivec4 frame_screen;
  vec4 frame_ray00;   // camera ray of pixel coordinate (0, 0) at view depth 1 (exec::PixelRays)
  vec4 frame_ray_dx;  // its change per pixel right
  vec4 frame_ray_dy;  // and up
};
