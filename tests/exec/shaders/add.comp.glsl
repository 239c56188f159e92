#version 450 core
// Compute test pass: dst = src + amount (src sampled, dst written as an image).
#include "screen_pass.glsl"
uniform sampler2D u_src;
layout(r32f, binding = 0) uniform writeonly image2D u_dst;
uniform float u_amount;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_dst)))) return;
  imageStore(u_dst, p, texelFetch(u_src, p, 0) + vec4(u_amount));
}
