#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Debug view of Cherry & Kooima's Figure 4 ("a special penumbra type that clearly distinguishes
// umbrae from penumbrae regions. The dark lines indicate penumbra and the shaded portion within
// is the umbra"), from the final shadow_mask:
//   lit (mask >= 0.99)       white
//   penumbra                 dark blue gradient, darkest at the umbra side
//   umbra (mask <= 0.01)     mid grey with diagonal hatching
//   background               black
#include "screen_pass.glsl"

layout(rgba8, binding = 0) uniform writeonly image2D u_output;
uniform sampler2D u_mask;      // visibility, 1 = lit
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_output)))) return;
  float m = texelFetch(u_mask, p, 0).r;
  vec3 c;
  if (gbuffer_position(u_depth, p).w <= 0.0) c = vec3(0.0);
  else if (m >= 0.99) c = vec3(1.0);
  else if (m <= 0.01) c = ((p.x + p.y) % 8 < 2) ? vec3(0.45) : vec3(0.65);
  else c = mix(vec3(0.02, 0.02, 0.12), vec3(0.35, 0.4, 0.75), m);
  imageStore(u_output, p, vec4(c, 1.0));
}
