#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Shadow filtering (section 1), separable variant, second pass: the rows of
// shadow_filter_x.comp.glsl filtered along the pixel's column by the same cross-bilateral
// Gaussian of diameter W_screen (this pixel's), giving the shadow mask (1 = lit, 0 = umbra). A
// row counts in proportion to the share of its kernel the range term kept.
// Background: 1. A receiver facing away from the light: 0 (its own shadow). W_screen = 0: the
// hard visibility.
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "sampling/sampling.glsl"
#include "screen_geometry.glsl"
#include "range_term.glsl"
#include "receiver_footprint.glsl"
#include "separable_taps.glsl"

layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_projected;  // prepare.comp.glsl: r = hard visibility, b = view depth, a = faces away
uniform sampler2D u_penumbra;   // W_screen, pixels
uniform sampler2D u_rows;       // shadow_filter_x.comp.glsl: r = visibility, g = kept share, b = view depth

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  vec4 own = texelFetch(u_projected, p, 0);
  float width = texelFetch(u_penumbra, p, 0).r;
  float visibility = own.r;
  if (own.b <= 0.0) {
    visibility = 1.0;
  } else if (own.a > 0.5) {
    visibility = 0.0;
  } else if (width > 0.0) {
    vec3 normal = gbuffer_normal(u_normal, p);
    mat2 footprint = receiver_footprint(p, gbuffer_position(u_depth, p).xyz, normal);
    RangeCentre centre = range_centre(p, own.b, normal);
    SeparableKernel kernel = separable_kernel(footprint, width);
    width = kernel.width_y;
    AxisTaps taps = axis_taps(width, interleaved_gradient_noise(vec2(p) + vec2(53.0, 11.0)));
    float weight = 0.0, sum = 0.0;
    for (int i = 0; i < taps.count; ++i) {
      int o = tap_offset(taps, i);
      ivec2 q = p + ivec2(int(round(kernel.shear * float(o))), o);
      if (!inside_screen(q)) continue;
      vec3 row = texelFetch(u_rows, q, 0).rgb;
      float w = gaussian_weight(o, width) * range_weight(centre, q, row.b) * row.g;
      weight += w;
      sum += w * row.r;
    }
    if (weight > 0.0) visibility = sum / weight;
  }
  imageStore(u_mask, p, vec4(clamp(visibility, 0.0, 1.0)));
}
