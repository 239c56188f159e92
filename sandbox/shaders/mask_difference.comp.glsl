#version 450 core
// Error image of compare mode: a - b of two shadow masks (visibility, 1 = lit) per pixel, signed
// (negative: A darker than B, the reference), and receiver coverage (gbuffer_depth > 0 on
// geometry, see technique/frame_graph.h) so the display greys out the background as the CLI's
// heat maps do. r = a - b, g = coverage (0 or 1).
#include "screen_pass.glsl"
layout(binding = 0, rg16f) uniform writeonly image2D difference;
uniform sampler2D mask_a;
uniform sampler2D mask_b;
uniform sampler2D depth;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(difference)))) return;
  float a = texelFetch(mask_a, p, 0).r;
  float b = texelFetch(mask_b, p, 0).r;
  float covered = texelFetch(depth, p, 0).r > 0.0 ? 1.0 : 0.0;
  imageStore(difference, p, vec4(a - b, covered, 0.0, 0.0));
}
