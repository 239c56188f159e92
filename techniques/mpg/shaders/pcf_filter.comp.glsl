#version 450 core
// Pass 4, PCF alteration (Cherry & Kooima, section 3.1): S averaged over a box whose size is
// driven by D, size = clamp(D, 1, max_kernel) pixels (1 x 1 = unfiltered up to 19 x 19 by
// default; Figure 5E). N^2 taps (section 2.1). A fractional size fades the outer ring in
// (kernel_coverage), so the penumbra widens continuously with D. The box is laid out on the round
// unit kernel and mapped to the screen by the pixel's kernel shape A (kernel_shape.glsl; identity
// when `anisotropic` is off), so taps fall between texels and are read bilinearly. Reads the
// distance map as it was after passes 2-3, writes the filtered S to the next version.
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
  vec4 centre = texelFetch(u_distance_map, p, 0);
  float kernel = clamp(centre.g, 1.0, u_max_kernel);
  if (centre.g > 0.0 && kernel > 1.0) {
    vec4 shape = texelFetch(u_kernel_shape, p, 0);
    vec3 a = decode_shape(shape);
    vec2 texel = 1.0 / vec2(size), here = vec2(p) + 0.5;
    int r = int(ceil(0.5 * (kernel - 1.0)));
    float sum = 0.0, weights = 0.0;
    for (int y = -r; y <= r; ++y)
      for (int x = -r; x <= r; ++x) {
        vec2 o = shape_offset(a, vec2(x, y));
        vec4 v = textureLod(u_distance_map, (here + o) * texel, 0.0);
        float w = kernel_coverage(float(x), kernel) * kernel_coverage(float(y), kernel) *
                  tap_depth_weight(centre.b, shape.zw, o, v.b);
        sum += w * v.r;
        weights += w;
      }
    centre.r = sum / weights;  // the centre tap always counts: weights > 0
  }
  imageStore(u_output, p, centre);
}
