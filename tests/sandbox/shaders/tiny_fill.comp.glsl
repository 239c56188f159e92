#version 450 core
// Test pattern for the sandbox tests: `level` inside stripes (or checker cells) of
// `stripe_width` pixels on geometry, 1 (lit) elsewhere.
#include "screen_pass.glsl"
layout(binding = 0, r16f) uniform writeonly image2D mask;
uniform sampler2D depth;  // gbuffer_depth: 0 on background
uniform float level;
uniform int stripe_width;  // pixels
uniform int pattern;       // 0 stripes, 1 checker

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(mask)))) return;
  ivec2 cell = p / max(stripe_width, 1);
  bool inside = pattern == 0 ? (cell.x % 2 == 0) : ((cell.x + cell.y) % 2 == 0);
  bool geometry = texelFetch(depth, p, 0).r > 0.0;
  imageStore(mask, p, vec4(inside && geometry ? level : 1.0));
}
