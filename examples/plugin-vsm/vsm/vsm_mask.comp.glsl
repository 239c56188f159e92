#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// vsm_mask: one thread per screen pixel. The receiver's light distance t against the moments
// (mean m1, mean of squares m2) at its shadow-map texel: lit when t <= m1, else the Chebyshev
// bound s^2 / (s^2 + (t - m1)^2), s^2 = max(m2 - m1^2, min_variance), with light-bleeding
// reduction (Lauritzen, GPU Gems 3 ch. 8): visibility below u_bleeding is 0, the rest rescaled.
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"

layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_moments;   // (mean, mean of squares) of the light distance, world units
uniform float u_min_variance;  // world units^2
uniform float u_bleeding;      // [0, 1)

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  vec4 pos = gbuffer_position(u_depth, p);
  float lit = 1.0;
  if (pos.w > 0.0) {
    vec3 c = shadow_coord(pos.xyz);
    if (all(greaterThanEqual(c, vec3(0.0))) && all(lessThanEqual(c, vec3(1.0)))) {
      vec2 m = textureLod(u_moments, c.xy, 0.0).rg;
      float t = light_distance(c.z);
      if (t > m.x) {
        float variance = max(m.y - m.x * m.x, u_min_variance);
        float dt = t - m.x;
        float p_max = variance / (variance + dt * dt);
        lit = clamp((p_max - u_bleeding) / (1.0 - u_bleeding), 0.0, 1.0);
      }
    }
  }
  imageStore(u_mask, p, vec4(lit));
}
