#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Raster reference: shadow_mask = accumulated visibility / samples accumulated (1 = lit).
// Background pixels are written 1 (lit), as the ray-traced reference does.
#include "screen_pass.glsl"
layout(r32f, binding = 0) uniform readonly image2D u_accumulation;
layout(r32f, binding = 1) uniform writeonly image2D u_mask;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform float u_count;  // samples in the sum (>= 1)

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  float v = 1.0;
  if (gbuffer_position(u_depth, p).w > 0.0) v = clamp(imageLoad(u_accumulation, p).r / u_count, 0.0, 1.0);
  imageStore(u_mask, p, vec4(v));
}
