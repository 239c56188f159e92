#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Shadow filtering (section 1), Poisson variant: the hard visibility of the projected shadow map
// (prepare.comp.glsl) averaged over a disk of diameter W_screen (this pixel's penumbra_width)
// with the cross-bilateral weights of section 2 (uniform disk domain x range term), giving the
// shadow mask (1 = lit, 0 = umbra). The centre pixel is always a tap. Background: 1. A receiver
// facing away from the light: 0 (its own shadow). W_screen = 0: the hard visibility.
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "sampling/sampling.glsl"
#include "screen_geometry.glsl"
#include "range_term.glsl"
#include "receiver_footprint.glsl"
#include "poisson_taps.glsl"

layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_projected;  // prepare.comp.glsl: r = hard visibility, b = view depth, a = faces away
uniform sampler2D u_penumbra;   // W_screen, pixels

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
    vec2 rotation = poisson_rotation(p);
    float weight = 1.0, sum = own.r;
    for (int i = 0; i < u_poisson_taps; ++i) {
      ivec2 q = p + poisson_offset(i, rotation, 0.5 * width, footprint);
      if (!inside_screen(q)) continue;
      vec4 s = texelFetch(u_projected, q, 0);
      float w = range_weight(centre, q, s.b);
      weight += w;
      sum += w * s.r;
    }
    visibility = sum / weight;
  }
  imageStore(u_mask, p, vec4(clamp(visibility, 0.0, 1.0)));
}
