#version 450 core
// Min-filter variant, first step (Sterna 2018, section 2.3): the minimum (closest to the light)
// window depth of each FACTOR x FACTOR block of the shadow map.
#include "screen_pass.glsl"
layout(r32f, binding = 0) uniform writeonly image2D u_min_depth;
uniform sampler2D u_shadow_map;  // raw window depth

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_min_depth);
  if (any(greaterThanEqual(p, size))) return;
  ivec2 src = textureSize(u_shadow_map, 0);
  ivec2 factor = max(src / size, ivec2(1));
  float m = 1.0;
  for (int y = 0; y < factor.y; ++y)
    for (int x = 0; x < factor.x; ++x)
      m = min(m, texelFetch(u_shadow_map, min(p * factor + ivec2(x, y), src - 1), 0).r);
  imageStore(u_min_depth, p, vec4(m));
}
