#version 450 core
// Writes the frame contract as a pass reads it: the rebuilt world position (w = view depth) and
// the decoded normal, and a lit shadow_mask.
#include "gbuffer/gbuffer_read.glsl"
#include "screen_pass.glsl"
layout(rgba32f, binding = 0) uniform writeonly image2D u_position_out;
layout(rgba32f, binding = 1) uniform writeonly image2D u_normal_out;
layout(r16f, binding = 2) uniform writeonly image2D u_mask;
uniform sampler2D u_depth;
uniform sampler2D u_normal;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  vec4 pos = gbuffer_position(u_depth, p);
  imageStore(u_position_out, p, pos);
  imageStore(u_normal_out, p, vec4(pos.w > 0.0 ? gbuffer_normal(u_normal, p) : vec3(0.0), 0.0));
  imageStore(u_mask, p, vec4(1.0));
}
