#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Blocker search (section 1), Poisson variant: one pass over a disk of diameter W_search
// (penumbra_estimate.glsl) around the pixel, u_poisson_taps taps of the projected shadow map
// (prepare.comp.glsl) with the shadow filter's edge-aware weights (section 2: uniform disk
// domain x range term); taps not in hard shadow are no blockers and are ignored. Then the
// penumbra estimate (section 1):
//   blocker  average blocker light distance, world units (0 = no blocker found)
//   penumbra W_screen, the shadow filter's diameter in pixels (0 = no blocker), clamped to
//            max_penumbra_px
// The centre pixel is always a tap (the disk set need not hold the centre).
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "sampling/sampling.glsl"
#include "screen_geometry.glsl"
#include "range_term.glsl"
#include "receiver_footprint.glsl"
#include "penumbra_estimate.glsl"
#include "poisson_taps.glsl"

layout(r32f, binding = 0) uniform writeonly image2D u_blocker;
layout(r16f, binding = 1) uniform writeonly image2D u_penumbra;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_projected;  // prepare.comp.glsl

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_blocker)))) return;
  vec4 pos = gbuffer_position(u_depth, p);
  float blocker = 0.0, penumbra = 0.0;
  if (pos.w > 0.0) {
    float d_receiver = light_distance_of(pos.xyz);
    vec3 normal = gbuffer_normal(u_normal, p);
    mat2 footprint = receiver_footprint(p, pos.xyz, normal);
    float radius = 0.5 * search_width_px(d_receiver, pos.w, footprint);
    RangeCentre centre = range_centre(p, pos.w, normal);
    vec2 rotation = poisson_rotation(p);
    vec4 own = texelFetch(u_projected, p, 0);
    float weight = 1.0 - own.r;  // a tap blocks in proportion to its occlusion
    float sum = weight * own.g;
    for (int i = 0; i < u_poisson_taps; ++i) {
      ivec2 q = p + poisson_offset(i, rotation, radius, footprint);
      if (!inside_screen(q)) continue;
      vec4 s = texelFetch(u_projected, q, 0);
      float w = range_weight(centre, q, s.b) * (1.0 - s.r);
      weight += w;
      sum += w * s.g;
    }
    if (weight > 0.0) blocker = sum / weight;
    penumbra = screen_penumbra_px(weight > 0.0, d_receiver, blocker, pos.w, footprint);
  }
  imageStore(u_blocker, p, vec4(blocker));
  imageStore(u_penumbra, p, vec4(penumbra));
}
