#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Blocker search (section 1), separable variant, first pass: along the pixel's row. Reads the
// projected shadow map (prepare.comp.glsl); taps that are not in hard shadow are no blockers and
// are ignored (section 1), the others are averaged with the edge-aware weights of the shadow
// filter (section 2: Gaussian domain x range term). Kernel diameter: the search width W_search
// of this pixel's receiver (penumbra_estimate.glsl), pixels.
// Output, per pixel (blocker_search_y.comp.glsl combines the rows):
//   r  mean light distance of the row's blockers (world units; 0 where none)
//   g  blocker coverage: their weight / the weight of every tap (in [0, 1])
//   b  the pixel's view depth (world units; 0 = background), for the next pass's range term
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "sampling/sampling.glsl"
#include "screen_geometry.glsl"
#include "range_term.glsl"
#include "receiver_footprint.glsl"
#include "penumbra_estimate.glsl"
#include "separable_taps.glsl"

layout(rgba16f, binding = 0) uniform writeonly image2D u_rows;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_projected;  // prepare.comp.glsl

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_rows)))) return;
  vec4 pos = gbuffer_position(u_depth, p);
  if (pos.w <= 0.0) {
    imageStore(u_rows, p, vec4(0.0));
    return;
  }
  float d_receiver = light_distance_of(pos.xyz);
  vec3 normal = gbuffer_normal(u_normal, p);
  mat2 footprint = receiver_footprint(p, pos.xyz, normal);
  float width = separable_kernel(footprint, search_width_px(d_receiver, pos.w, footprint)).width_x;
  RangeCentre centre = range_centre(p, pos.w, normal);
  AxisTaps taps = axis_taps(width, interleaved_gradient_noise(vec2(p)));
  float all_weight = 0.0, blocker_weight = 0.0, blocker_sum = 0.0;
  for (int i = 0; i < taps.count; ++i) {
    int o = tap_offset(taps, i);
    ivec2 q = p + ivec2(o, 0);
    if (!inside_screen(q)) continue;
    vec4 s = texelFetch(u_projected, q, 0);
    float w = gaussian_weight(o, width) * range_weight(centre, q, s.b);
    all_weight += w;
    float b = w * (1.0 - s.r);  // a tap blocks in proportion to its occlusion
    blocker_weight += b;
    blocker_sum += b * s.g;
  }
  float mean = blocker_weight > 0.0 ? blocker_sum / blocker_weight : 0.0;
  float coverage = all_weight > 0.0 ? blocker_weight / all_weight : 0.0;
  imageStore(u_rows, p, vec4(mean, coverage, pos.w, 0.0));
}
