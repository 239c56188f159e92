#version 450 core
// output = input * factor (the sandbox tests' second, optional pass).
#include "screen_pass.glsl"
layout(binding = 0, r16f) uniform writeonly image2D dst;
uniform sampler2D src;
uniform float factor;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(dst)))) return;
  imageStore(dst, p, vec4(texelFetch(src, p, 0).r * factor));
}
