#version 450 core
// One axis of a separable filter (2 * radius + 1 taps along u_axis), every channel of any colour
// format (IMAGE_FORMAT is the output's qualifier, set by the pass from the bound texture):
//   MODE 0 gaussian   weights exp(-i^2 / (2 sigma^2)), normalised
//   MODE 1 max        per channel
//   MODE 2 min        per channel
//   MODE 3 copy       radius 0 (keeps a graph edge when a stage is switched off)
//   MODE 4 box        equal weights
//   MODE 5 bilateral  gaussian times exp(-(d_i - d_0)^2 / (2 depth_sigma^2)), d from u_depth's
//                     first channel: taps across a depth edge barely count
// Taps outside the texture are clamped to the edge.
// SIGMA_FROM_LIGHT 1 (gaussian, bilateral; u_input covers the shadow map): sigma is the standard
// deviation of the frame light's penumbra across an edge u_penumbra_height x the scene's height
// along the light's rays (u_blocker_height_scale) above its receiver,
// width / 4 (a disk's chord-length profile, the semicircle distribution of radius width / 2, has
// that deviation), at most MAX_RADIUS / 3; radius ceil(3 sigma).
#include "screen_pass.glsl"
#if SIGMA_FROM_LIGHT
#include "common/shadow_common.glsl"
uniform float u_penumbra_height;  // a fraction of u_blocker_height_scale
#endif
layout(IMAGE_FORMAT, binding = 0) uniform writeonly image2D u_output;
uniform sampler2D u_input;
uniform sampler2D u_depth;    // MODE 5 only, same size as u_input
uniform ivec2 u_axis;         // (1, 0) horizontal, (0, 1) vertical
uniform int u_radius;         // texels
uniform float u_sigma;        // texels (gaussian, bilateral)
uniform float u_depth_sigma;  // u_depth's units (bilateral)

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_output);
  if (any(greaterThanEqual(p, size))) return;
  vec4 result = texelFetch(u_input, p, 0);
  int radius = u_radius;
  float sigma = u_sigma;
#if SIGMA_FROM_LIGHT
  sigma = min(0.25 * edge_penumbra_width_uv(u_penumbra_height * u_blocker_height_scale) * float(textureSize(u_input, 0).x),
              float(MAX_RADIUS) / 3.0);
  radius = int(ceil(3.0 * sigma));
#endif
#if MODE == 0 || MODE == 4 || MODE == 5
#if MODE == 5
  float d0 = texelFetch(u_depth, p, 0).r;
#endif
  vec4 sum = vec4(0.0);
  float weights = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    ivec2 q = clamp(p + i * u_axis, ivec2(0), size - 1);
#if MODE == 4
    float w = 1.0;
#else
    float w = exp(-float(i * i) / (2.0 * sigma * sigma));
#endif
#if MODE == 5
    float dd = texelFetch(u_depth, q, 0).r - d0;
    w *= exp(-dd * dd / (2.0 * u_depth_sigma * u_depth_sigma));
#endif
    sum += w * texelFetch(u_input, q, 0);
    weights += w;
  }
  result = sum / weights;  // the centre tap has weight 1: never 0
#elif MODE == 1 || MODE == 2
  for (int i = -radius; i <= radius; ++i) {
    vec4 v = texelFetch(u_input, clamp(p + i * u_axis, ivec2(0), size - 1), 0);
#if MODE == 1
    result = max(result, v);
#else
    result = min(result, v);
#endif
  }
#endif
  imageStore(u_output, p, result);
}
