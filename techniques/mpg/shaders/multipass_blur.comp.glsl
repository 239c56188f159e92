#version 450 core
// Pass 4, multi-pass Gaussian alteration (Cherry & Kooima, sections 3.1-3.2): ONE blur pass; the
// graph repeats it max_passes times (`repeat`), each reading what the previous one wrote.
//   D <= 0: the pixel is not blurred, now or later (it started at 0 or was counted down).
//   D > 0:  S = sum over taps of weight_i * S(p + offset_i), then D = D - 1.
// Taps (u_taps, computed on the CPU per pass: multipass_kernel.cpp): the first poisson_taps
// points of a Poisson disk in [-1, 1]^2 (the first at the origin) times (KS - 1) / 2 pixels, KS
// this pass's kernel size (fixed, or 3x3 growing to max_kernel), with normalised Gaussian weights
// (sigma = KS / 3). Offsets lie on the round unit kernel and are mapped to the screen by the
// pixel's kernel shape A (kernel_shape.glsl; identity when `anisotropic` is off); they are
// fractional, so the distance map is sampled bilinearly. DENSE: every texel of the KS x KS unit
// kernel instead (Figure 7's "entire Gaussian", KS^2 taps).
// A D below 1 on its last pass blends the blur in by D (not in the paper, which blurs fully while
// D > 0): the penumbra then follows a continuous D instead of stepping at whole passes.
// Lit pixels have D = 0 unless dilated (pass 3), so without dilation they stay exactly S = 0:
// the passes only lighten shadowed pixels, growing the inner penumbra (section 5).
#include "screen_pass.glsl"
#include "mpg_common.glsl"
#include "shape_offset.glsl"

layout(rgba16f, binding = 0) uniform writeonly image2D u_output;
uniform sampler2D u_distance_map;  // linear, clamp to edge
uniform sampler2D u_kernel_shape;  // (A11, A12, dz/dx, dz/dy), texelFetch
uniform vec4 u_taps[64];           // xy: offset in pixels, z: normalised weight
uniform int u_tap_count;
uniform int u_kernel_size;         // KS, pixels (dense)
#if SCREEN_TILED
// Passes after the first, over the tiles with D > 0 (blur_tiles.comp.glsl): the output texture
// holds what the pass before last wrote; a tile that changed on neither that pass nor the last
// (it changes on passes 0 .. m - 1, m from u_tile_passes) already holds this pass's answer.
uniform sampler2D u_tile_passes;
uniform int u_iteration;
#endif

void main() {
#if SCREEN_TILED
  if (float(u_iteration) > texelFetch(u_tile_passes, ivec2(tile_list_tile()), 0).r) return;
#endif
  ivec2 p = screen_pixel();
  ivec2 size = imageSize(u_output);
  if (any(greaterThanEqual(p, size))) return;
  vec4 centre = texelFetch(u_distance_map, p, 0);
  if (centre.g > 0.0) {
    vec4 shape = texelFetch(u_kernel_shape, p, 0);
    vec3 a = decode_shape(shape);
    vec2 texel = 1.0 / vec2(size);
    vec2 here = vec2(p) + 0.5;
    float sum = 0.0, weights = 0.0;
#if DENSE
    int r = (u_kernel_size - 1) / 2;
    float sigma = float(u_kernel_size) / 3.0;
    for (int y = -r; y <= r; ++y)
      for (int x = -r; x <= r; ++x) {
        vec2 o = shape_offset(a, vec2(x, y));
        vec4 v = textureLod(u_distance_map, (here + o) * texel, 0.0);
        float w = exp(-float(x * x + y * y) / (2.0 * sigma * sigma)) * tap_depth_weight(centre.b, shape.zw, o, v.b);
        sum += w * v.r;
        weights += w;
      }
#else
    for (int i = 0; i < u_tap_count; ++i) {
      vec2 o = shape_offset(a, u_taps[i].xy);
      vec4 v = textureLod(u_distance_map, (here + o) * texel, 0.0);
      float w = u_taps[i].z * tap_depth_weight(centre.b, shape.zw, o, v.b);
      sum += w * v.r;
      weights += w;
    }
#endif
    if (weights > 0.0) centre.r = mix(centre.r, sum / weights, min(centre.g, 1.0));
    centre.g = max(centre.g - 1.0, 0.0);
  }
  imageStore(u_output, p, centre);
}
