#version 450 core
// Pass 4, single-pass Gaussian alteration (Cherry & Kooima, section 3.1; SSSS-like, section 2.2):
// S filtered by a Gaussian whose size is driven by D, size = clamp(D, 1, max_kernel) pixels,
// sigma = size / 3 (Figure 5F), taps within +-size/2 (the outer ring fades in with a fractional
// size, kernel_coverage). Separable: 2N taps (section 2.1), so it runs as two dispatches,
// AXIS 0 (x) then AXIS 1 (y) of the round unit kernel, mapped to the screen by the pixel's
// kernel shape A (kernel_shape.glsl): the passes run along A's two columns, which keeps the 2-D
// kernel separable (g(u) g(v) at offset u A e_x + v A e_y); taps are read bilinearly. Both use
// the centre pixel's D, which the x pass copies through.
#include "screen_pass.glsl"
#include "mpg_common.glsl"
#include "shape_offset.glsl"

layout(rgba16f, binding = 0) uniform writeonly image2D u_output;
uniform sampler2D u_distance_map;  // linear, clamp to edge
uniform sampler2D u_kernel_shape;  // (A11, A12, dz/dx, dz/dy), texelFetch
uniform float u_max_kernel;        // pixels

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_output);
  if (any(greaterThanEqual(p, size))) return;
#if AXIS == 0
  const vec2 axis = vec2(1.0, 0.0);
#else
  const vec2 axis = vec2(0.0, 1.0);
#endif
  vec4 centre = texelFetch(u_distance_map, p, 0);
  float kernel = clamp(centre.g, 1.0, u_max_kernel);
  if (centre.g > 0.0 && kernel > 1.0) {
    vec4 shape = texelFetch(u_kernel_shape, p, 0);
    vec2 step = shape_offset(decode_shape(shape), axis);  // pixels per unit-kernel texel
    vec2 texel = 1.0 / vec2(size), here = vec2(p) + 0.5;
    int r = int(ceil(0.5 * (kernel - 1.0)));
    float sum = 0.0, weights = 0.0;
    for (int t = -r; t <= r; ++t) {
      vec2 o = float(t) * step;
      vec4 v = textureLod(u_distance_map, (here + o) * texel, 0.0);
      float w = kernel_gaussian(float(t), kernel) * kernel_coverage(float(t), kernel) *
                tap_depth_weight(centre.b, shape.zw, o, v.b);
      sum += w * v.r;
      weights += w;
    }
    centre.r = sum / weights;
  }
  imageStore(u_output, p, centre);
}
