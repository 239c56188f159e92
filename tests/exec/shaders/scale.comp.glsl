#version 450 core
// In-place compute test pass: img *= factor (image load/store on one texture).
#include "screen_pass.glsl"
layout(r32f, binding = 0) uniform image2D u_img;
uniform float u_factor;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_img)))) return;
  imageStore(u_img, p, imageLoad(u_img, p) * u_factor);
}
