#version 450 core
// Pass 5 (Cherry & Kooima, section 3.2): the frame's shadow_mask from the filtered distance map,
// visibility = 1 - S (S = 0 lit, 1 umbra, between: penumbra). Background pixels have S = 0.
#include "screen_pass.glsl"

layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_distance_map;  // texelFetch

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  float s = texelFetch(u_distance_map, p, 0).r;
  imageStore(u_mask, p, vec4(clamp(1.0 - s, 0.0, 1.0)));
}
