#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Full-resolution shadow mask (Sterna 2018): FILTER_SAMPLES Vogel taps of hardware comparison
// over a kernel of penumbra x shadow_filter_max_size (Listing 6). Where the penumbra comes from
// is PENUMBRA_SOURCE (a define, chosen by the graph's variant):
//   0 search:    the regular CHSS blocker search in this pass (section 2.1, Listing 3)
//   1 mask:      the penumbra mask, sampled bilinearly at the pixel (section 2.2)
//   2 min_depth: the blurred min-filtered shadow map as the blocker depth (section 2.3)
// CHECKER (define): only pixels with (x + y) even are computed (section 3, Listing 7). The
// packed target is RG16F at screen/2: texel (cx, cy) holds pixel (2cx, 2cy) in .r and
// (2cx + 1, 2cy + 1) in .g, i.e. the same texel count x channels as the paper's half-width
// R target (the graph's size expressions have no half-width form).
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "sampling/sampling.glsl"
#include "common/receiver_plane.glsl"
#include "pmchss_common.glsl"

#ifdef CHECKER
layout(rg16f, binding = 0) uniform writeonly image2D u_mask;
#else
layout(r16f, binding = 0) uniform writeonly image2D u_mask;
#endif
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_shadow_map;        // raw window depth, nearest
uniform sampler2DShadow u_shadow_cmp;  // same texture, linear + depth comparison
#if PENUMBRA_SOURCE == 1
uniform sampler2D u_penumbra_mask;     // low resolution, linear clamp
#elif PENUMBRA_SOURCE == 2
uniform sampler2D u_min_depth;         // shadow/4 blurred min window depth, linear clamp
#endif

float shadow_at(ivec2 pixel, ivec2 screen, bool checker) {
  vec4 pos = gbuffer_position(u_depth, pixel);
  if (pos.w <= 0.0) return 1.0;  // background: lit, by the shadow_mask contract
  // A receiver facing away from the light is in its own shadow (closed geometry); its depth is
  // too close to the occluding front face for any bias to classify it reliably.
  if (faces_away_from_light(pos.xyz, gbuffer_normal(u_normal, pixel))) return 0.0;
  if (!pmchss_in_shadow_frustum(shadow_coord(pos.xyz))) return 1.0;
  Receiver r = pmchss_receiver(u_depth, u_normal, pixel, pos.xyz);
  vec3 c = r.coord;
  float phi = pmchss_noise_phi(r, pixel, checker);
#if PENUMBRA_MAPPING == 2
  float penumbra = 1.0;  // fixed kernel: Table 1's "Regular Shadow Mask", no search at all
#elif PENUMBRA_SOURCE == 0
  float blocker;
  float count = pmchss_blocker_search(u_shadow_map, r, BLOCKER_SAMPLES, phi, blocker);
  float penumbra = count > 0.0 ? pmchss_penumbra_from_blocker(receiver_light_distance(r), blocker) : 0.0;
#elif PENUMBRA_SOURCE == 1
  float penumbra = textureLod(u_penumbra_mask, (vec2(pixel) + 0.5) / vec2(screen), 0.0).r;
#else
  // Section 2.3: the min depth is used directly as the average blocker depth (six faces: its
  // block's distance along the receiver's ray).
  float min_distance = light_distance(textureLod(u_min_depth, c.xy, 0.0).r) * pmchss_tap(r, vec2(0.0)).distance_scale;
  float penumbra = pmchss_penumbra_from_blocker(receiver_light_distance(r), min_distance);
#endif
  return clamp(pmchss_filter(u_shadow_cmp, r, penumbra, phi), 0.0, 1.0);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 target = imageSize(u_mask);
  if (any(greaterThanEqual(p, target))) return;
  ivec2 screen = textureSize(u_depth, 0);
#ifdef CHECKER
  ivec2 even_row = ivec2(2 * p.x, 2 * p.y);          // (x + y) even on row 2cy
  ivec2 odd_row = ivec2(2 * p.x + 1, 2 * p.y + 1);   // and on row 2cy + 1
  float a = all(lessThan(even_row, screen)) ? shadow_at(even_row, screen, true) : 1.0;
  float b = all(lessThan(odd_row, screen)) ? shadow_at(odd_row, screen, true) : 1.0;
  imageStore(u_mask, p, vec4(a, b, 0.0, 0.0));
#else
  imageStore(u_mask, p, vec4(shadow_at(p, screen, false)));
#endif
}
