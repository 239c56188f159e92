#version 450 core
// vsm_moments: one thread per shadow-map texel. The mean of the light distance d (world units,
// shadow_common.glsl's light_distance) and of d^2 over a (2r+1)^2 box of the shadow map.
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"

layout(rg32f, binding = 0) uniform writeonly image2D u_moments;
uniform sampler2D u_shadow_map;  // light window depth
uniform int u_radius;            // texels

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_moments);
  if (any(greaterThanEqual(p, size))) return;
  vec2 sum = vec2(0.0);
  for (int y = -u_radius; y <= u_radius; ++y)
    for (int x = -u_radius; x <= u_radius; ++x) {
      float d = light_distance(texelFetch(u_shadow_map, clamp(p + ivec2(x, y), ivec2(0), size - 1), 0).r);
      sum += vec2(d, d * d);
    }
  float taps = float((2 * u_radius + 1) * (2 * u_radius + 1));
  imageStore(u_moments, p, vec4(sum / taps, 0.0, 0.0));
}
