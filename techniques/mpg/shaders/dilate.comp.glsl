#version 450 core
// Pass 3, dilation of D (Cherry & Kooima, section 3.1: "apply a Gaussian filter over the
// channel to expand the penumbra region"), one axis of a separable pass.
//
// A normalised Gaussian average would also halve D on the shadowed side of every edge (its lit
// neighbours have D = 0) and shrink the inner penumbra; we use the Gaussian DILATION instead
// (grey-scale morphology with a Gaussian structuring function, product form):
//   D'(p) = max over q in the K x K kernel of D(q) * g(q - p),  g(0) = 1, sigma = K / 3 pixels
// which never lowers D and spreads an edge's D outwards with a Gaussian fall-off. The product
// g(x) g(y) makes it separable: AXIS 0 writes the row maximum to .a, AXIS 1 takes the column
// maximum of .a. Only LIT pixels (S = 0) take the dilated value: that is the outer penumbra the
// paper says this pass controls (section 5); shadowed pixels keep their own D, so a receiver's
// own umbra (faces away from the light) and pixels the umbra early-out froze stay unfiltered.
// Depth-aware (mpg_common.glsl): D does not spread to another surface. The two axes are those of
// the round unit kernel mapped by the pixel's kernel shape A (kernel_shape.glsl), so D reaches
// along the receiver's penumbra footprint; taps are the nearest texels (a bilinear D would mix
// in the zeros of lit texels).
#include "screen_pass.glsl"
#include "mpg_common.glsl"
#include "shape_offset.glsl"

layout(rgba16f, binding = 0) uniform writeonly image2D u_output;
uniform sampler2D u_distance_map;  // texelFetch
uniform sampler2D u_kernel_shape;  // (A11, A12, dz/dx, dz/dy), texelFetch
uniform int u_radius;              // (K - 1) / 2 pixels
uniform float u_kernel;            // K, pixels
#if INPUT_MARKS
// Tiles whose input channel this pass dilates may be non-zero (tile_marks.glsl): D for AXIS 0
// (pass 2's d_tiles), the row maxima .a for AXIS 1 (AXIS 0's a_tiles). A tap lies at most
// u_radius * 2.5 + 1 pixels from its pixel (a shaped axis stretches by at most sqrt(6)): with no
// marked tile within that reach, every tap would give 0.
uniform sampler2D u_input_marks;
uniform int u_tile_reach;  // tiles
#endif
#if OUTPUT_MARKS
layout(r8, binding = 1) uniform writeonly image2D u_output_marks;  // tiles with a non-zero .a (AXIS 0)
#endif
#if INPUT_MARKS || OUTPUT_MARKS
#include "tile_marks.glsl"
#endif
#if BLUR_LIST
// AXIS 1 sets D for the last time before the multi-pass blur: it lists the blur's tiles.
layout(r16f, binding = 2) uniform writeonly image2D u_tile_passes;
#include "blur_tile_list.glsl"
#endif

// Dilates pixel p and writes it; returns what it wrote.
vec4 dilate(ivec2 p, ivec2 size, bool near) {
  vec4 centre = texelFetch(u_distance_map, p, 0);
  vec4 shape = texelFetch(u_kernel_shape, p, 0);
#if AXIS == 0
  vec2 step = shape_offset(decode_shape(shape), vec2(1.0, 0.0));
#else
  vec2 step = shape_offset(decode_shape(shape), vec2(0.0, 1.0));
#endif
  float sigma = u_kernel / 3.0;
  float dilated = 0.0;
  // Taps are spent only where their result is used: AXIS 1 changes lit receivers alone, and
  // AXIS 0's row maximum of a background pixel is a tap AXIS 1 weighs 0 when depth-aware.
  // Exact: the same D as walking every pixel.
#if AXIS == 0
  bool used = near && (centre.b > 0.0 || u_depth_aware == 0);
#else
  bool used = near && centre.r == 0.0 && centre.b > 0.0;
#endif
  for (int t = -u_radius; used && t <= u_radius; ++t) {
    ivec2 q = ivec2(floor(vec2(p) + 0.5 + float(t) * step));
    vec2 o = vec2(q - p);
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
    vec4 v = texelFetch(u_distance_map, q, 0);
#if AXIS == 0
    float d = v.g;
#else
    float d = v.a;
#endif
    float g = exp(-float(t * t) / (2.0 * sigma * sigma)) * tap_depth_weight(centre.b, shape.zw, o, v.b);
    dilated = max(dilated, d * g);
  }
#if AXIS == 0
  centre.a = dilated;
#else
  if (centre.r == 0.0 && centre.b > 0.0) centre.g = max(centre.g, dilated);
  centre.a = 0.0;
#endif
  imageStore(u_output, p, centre);
  return centre;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_output);
  bool inside = all(lessThan(p, size));
#if INPUT_MARKS
  bool near = tile_marks_near(u_input_marks, u_tile_reach);
#else
  bool near = true;
#endif
#if OUTPUT_MARKS
  tile_marks_begin();
  if (inside) tile_marks_note(dilate(p, size, near).a > 0.0);
  bool marked = tile_marks_end();
  if (gl_LocalInvocationIndex == 0u) imageStore(u_output_marks, ivec2(gl_WorkGroupID.xy), vec4(marked ? 1.0 : 0.0));
#elif BLUR_LIST
  blur_list_begin();
  if (inside) blur_list_note(dilate(p, size, near).g);
  blur_list_end();
#else
  if (inside) dilate(p, size, near);
#endif
}
