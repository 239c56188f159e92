#version 450 core
// Compute test pass: img = max(img, x < 4 ? low : high) by an atomic MAX of the float bits.
#include "screen_pass.glsl"
layout(r32ui, binding = 0) uniform uimage2D u_img;
uniform float u_low;
uniform float u_high;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_img)))) return;
  imageAtomicMax(u_img, p, floatBitsToUint(p.x < 4 ? u_low : u_high));
}
