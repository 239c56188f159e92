#version 450 core
// Hard shadow: one depth comparison per pixel at the nearest shadow-map texel; the mask is
// exactly 0 or 1. A receiver that faces away from the light is 0 too; its normal is read only
// where the comparison says lit, since a shadowed pixel is 0 either way (4 of the pass's 9
// contract bytes a pixel are the normal).
#include "screen_pass.glsl"
#include "gbuffer/gbuffer_read.glsl"
#include "common/shadow_common.glsl"
layout(MASK_QUALIFIER, binding = 0) uniform writeonly image2D u_mask;  // the mask texture's format (a define)
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_shadow_map;   // raw depth, nearest
uniform float u_depth_bias;       // window depth units

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  vec4 pos = gbuffer_position(u_depth, p);
  float lit = 1.0;
  if (pos.w > 0.0) {
    vec3 c = shadow_coord(pos.xyz);
    if (all(greaterThanEqual(c, vec3(0.0))) && all(lessThanEqual(c, vec3(1.0)))) {
      ivec2 size = textureSize(u_shadow_map, 0);
      ivec2 t = clamp(ivec2(c.xy * vec2(size)), ivec2(0), size - 1);
      float blocker = texelFetch(u_shadow_map, t, 0).r;
      lit = c.z - u_depth_bias <= blocker ? 1.0 : 0.0;
    }
    if (lit > 0.0 && faces_away_from_light(pos.xyz, gbuffer_normal(u_normal, p))) lit = 0.0;
  }
  imageStore(u_mask, p, vec4(lit));
}
