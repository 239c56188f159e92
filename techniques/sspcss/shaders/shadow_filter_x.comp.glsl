#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Shadow filtering (section 1), separable variant, first pass: the hard visibility of the
// projected shadow map (prepare.comp.glsl) filtered along the pixel's row by the cross-bilateral
// Gaussian (section 2) of diameter W_screen, this pixel's (blocker_search_*: penumbra_width).
// W_screen = 0 (no blocker found, or a contact) keeps the hard visibility.
// Output, per pixel (shadow_filter_y.comp.glsl combines the rows):
//   r  filtered visibility in [0, 1]
//   g  the share of the row kernel's weight left by the range term (in [0, 1]): a row that
//      crosses a depth edge counts less in the column pass, as its taps would in a 2D filter
//   b  the pixel's view depth (world units; 0 = background), the next pass's range term input
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "sampling/sampling.glsl"
#include "screen_geometry.glsl"
#include "range_term.glsl"
#include "receiver_footprint.glsl"
#include "separable_taps.glsl"

layout(rgba16f, binding = 0) uniform writeonly image2D u_rows;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_projected;  // prepare.comp.glsl: r = hard visibility, b = view depth
uniform sampler2D u_penumbra;   // W_screen, pixels

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_rows)))) return;
  vec4 own = texelFetch(u_projected, p, 0);
  float width = texelFetch(u_penumbra, p, 0).r;
  float visibility = own.r, kept = 1.0;
  if (own.b > 0.0 && width > 0.0) {
    vec3 normal = gbuffer_normal(u_normal, p);
    mat2 footprint = receiver_footprint(p, gbuffer_position(u_depth, p).xyz, normal);
    RangeCentre centre = range_centre(p, own.b, normal);
    width = separable_kernel(footprint, width).width_x;
    AxisTaps taps = axis_taps(width, interleaved_gradient_noise(vec2(p) + vec2(7.0, 89.0)));
    float weight = 0.0, domain = 0.0, sum = 0.0;
    for (int i = 0; i < taps.count; ++i) {
      int o = tap_offset(taps, i);
      ivec2 q = p + ivec2(o, 0);
      if (!inside_screen(q)) continue;
      vec4 s = texelFetch(u_projected, q, 0);
      float g = gaussian_weight(o, width);
      float w = g * range_weight(centre, q, s.b);
      domain += g;
      weight += w;
      sum += w * s.r;
    }
    if (weight > 0.0) visibility = sum / weight;
    kept = domain > 0.0 ? weight / domain : 0.0;
  }
  imageStore(u_rows, p, vec4(visibility, kept, own.b, 0.0));
}
