#version 450 core
// Umbra early-out (Cherry & Kooima, section 5), one axis of a separable test: where every S in
// the N x N neighbourhood (N = umbra_neighbourhood, pixels) is shadowed, the pixel lies deep in
// an umbra and D becomes 0, so no later pass filters it.
//   AXIS 0 (x): .a = min of S over the N pixels of the row around the pixel
//   AXIS 1 (y): min of .a over the N pixels of the column; 1 means all N x N are shadowed -> D = 0
// The test needs S still binary, so it runs right after pass 2, before dilation. Taps beyond the
// screen edge repeat the edge pixel; background pixels have S = 0 and stop the early-out.
//
// Side effect (section 5): the blur passes make the inner penumbra (shadowed pixels lightened by
// lit neighbours); a pixel marked here is never blurred, so the inner penumbra cannot reach past
// (N - 1) / 2 pixels from the hard shadow edge. N must be at least max_kernel (checked by the
// pass), and larger to leave the multi-pass room to grow.
#include "screen_pass.glsl"

layout(rgba16f, binding = 0) uniform writeonly image2D u_output;
uniform sampler2D u_distance_map;  // texelFetch
uniform int u_radius;              // (N - 1) / 2 pixels

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_output);
  if (any(greaterThanEqual(p, size))) return;
  vec4 centre = texelFetch(u_distance_map, p, 0);
#if AXIS == 0
  const ivec2 step = ivec2(1, 0);
#else
  const ivec2 step = ivec2(0, 1);
#endif
  float all_shadowed = 1.0;
  for (int t = -u_radius; t <= u_radius && all_shadowed > 0.0; ++t) {
    vec4 v = texelFetch(u_distance_map, clamp(p + t * step, ivec2(0), size - 1), 0);
#if AXIS == 0
    all_shadowed = min(all_shadowed, v.r);
#else
    all_shadowed = min(all_shadowed, v.a);
#endif
  }
#if AXIS == 0
  centre.a = all_shadowed;
#else
  if (all_shadowed >= 1.0) centre.g = 0.0;
  centre.a = 0.0;
#endif
  imageStore(u_output, p, centre);
}
