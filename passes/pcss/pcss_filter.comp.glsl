#version 450 core
// PCSS steps 2 and 3 (Fernando 2005, section 3).
// Step 2, penumbra estimate, eq. 1 (similar triangles between emitter, blocker and receiver;
// d_r, d_b light distances in world units), with the light model of scene/light.h, in
// shadow-map UV at the receiver (penumbra_width_uv in shadow_common.glsl):
//   spot:        w = (d_r - d_b) * light_size / d_b, at the receiver's distance
//   directional: w = (d_r - d_b) * light_size / D, D = emitter plane to scene centre (a sun of
//                angular diameter size / D: the angular form of eq. 1)
// multiplied by light_size_scale and clamped to max_filter_uv.
// Step 3, filtering: PCF over a Vogel disk of diameter w_penumbra, `samples` taps rotated per
// pixel by 2 pi IGN(pixel), each a bilinear hardware comparison against the receiver plane.
// Pixels where the blocker search found nothing are exactly 1 (lit).
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "sampling/sampling.glsl"
#include "pcf_mask/shadow_taps.glsl"

layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_blocker;           // mean blocker distance, world units; 0 = none
uniform sampler2DShadow u_shadow_map;  // linear, clamp, depth compare (LEQUAL)
uniform float u_depth_bias;            // window depth
uniform int u_samples;
uniform float u_light_size_scale;
uniform float u_max_filter_uv;         // shadow-map UV

void main() {
  ivec2 p = screen_pixel();
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  float lit = 1.0;
  float d_b = texelFetch(u_blocker, p, 0).r;
  Receiver r;
  int kind = receiver_at(u_depth, u_normal, p, r);
  if (kind == RECEIVER_FACES_AWAY) {
    lit = 0.0;  // facing away from the light: no taps needed
  } else if (d_b > 0.0 && kind == RECEIVER_FILTERED) {
    add_receiver_plane(u_depth, p, r);
    float d_r = receiver_light_distance(r);
    float w_penumbra = min(penumbra_width_uv(d_r, d_b) * u_light_size_scale, u_max_filter_uv);
    float radius = 0.5 * w_penumbra;
    float phi = tap_rotation(r, vec2(p));
    float sum = 0.0;
    for (int i = 0; i < u_samples; ++i)
      sum += pcf_tap(u_shadow_map, r, vogel_disk_sample(i, u_samples, phi) * radius, u_depth_bias);
    lit = sum / float(u_samples);
  }
  imageStore(u_mask, p, vec4(lit));
}
