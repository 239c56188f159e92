#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// template_mask: one thread per screen pixel. Rebuilds the G-buffer position, projects it into
// the shadow map (shadow_common.glsl, found in passes/common) and writes the shadow mask
// (1 = lit). Replace the body with your technique.
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"

layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_shadow_map;  // light window depth
uniform float u_strength;        // the technique parameter shadow_strength, [0, 1]

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  vec4 pos = gbuffer_position(u_depth, p);
  float lit = 1.0;
  if (pos.w > 0.0) {
    vec3 c = shadow_coord(pos.xyz);  // (shadow-map uv, window depth)
    if (all(greaterThanEqual(c, vec3(0.0))) && all(lessThanEqual(c, vec3(1.0)))) {
      float occluder = textureLod(u_shadow_map, c.xy, 0.0).r;
      float occluded = c.z - 0.0005 > occluder ? 1.0 : 0.0;  // 0.0005: window-depth bias
      lit = 1.0 - u_strength * occluded;
    }
  }
  imageStore(u_mask, p, vec4(lit));
}
