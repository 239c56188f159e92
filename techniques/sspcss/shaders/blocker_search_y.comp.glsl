#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Blocker search (section 1), separable variant, second pass: along the pixel's column, over the
// rows of blocker_search_x.comp.glsl, with the same edge-aware weights; a row counts in
// proportion to its blocker coverage. Then the penumbra estimate (section 1) from the average
// blocker distance:
//   blocker  average blocker light distance, world units (0 = no blocker found)
//   penumbra W_screen, the shadow filter's diameter in pixels (0 = no blocker: the pixel keeps
//            its hard visibility), clamped to max_penumbra_px
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "sampling/sampling.glsl"
#include "screen_geometry.glsl"
#include "range_term.glsl"
#include "receiver_footprint.glsl"
#include "penumbra_estimate.glsl"
#include "separable_taps.glsl"

layout(r32f, binding = 0) uniform writeonly image2D u_blocker;
layout(r16f, binding = 1) uniform writeonly image2D u_penumbra;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_rows;      // blocker_search_x.comp.glsl

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_blocker)))) return;
  vec4 pos = gbuffer_position(u_depth, p);
  float blocker = 0.0, penumbra = 0.0;
  if (pos.w > 0.0) {
    float d_receiver = light_distance_of(pos.xyz);
    vec3 normal = gbuffer_normal(u_normal, p);
    mat2 footprint = receiver_footprint(p, pos.xyz, normal);
    SeparableKernel kernel = separable_kernel(footprint, search_width_px(d_receiver, pos.w, footprint));
    float width = kernel.width_y;
    RangeCentre centre = range_centre(p, pos.w, normal);
    // Another jitter than the rows' (shifted noise), so the two axes' strata do not line up.
    AxisTaps taps = axis_taps(width, interleaved_gradient_noise(vec2(p) + vec2(19.0, 47.0)));
    float weight = 0.0, sum = 0.0;
    for (int i = 0; i < taps.count; ++i) {
      int o = tap_offset(taps, i);
      ivec2 q = p + ivec2(int(round(kernel.shear * float(o))), o);
      if (!inside_screen(q)) continue;
      vec4 row = texelFetch(u_rows, q, 0);
      float w = gaussian_weight(o, width) * range_weight(centre, q, row.b) * row.g;
      weight += w;
      sum += w * row.r;
    }
    if (weight > 0.0) blocker = sum / weight;
    penumbra = screen_penumbra_px(weight > 0.0, d_receiver, blocker, pos.w, footprint);
  }
  imageStore(u_blocker, p, vec4(blocker));
  imageStore(u_penumbra, p, vec4(penumbra));
}
