#version 450 core
// One axis of a separable filter over a single-channel texture (2 * radius + 1 taps):
//   MODE 0 gaussian: the min-filter variant's small blur of the min depth map (section 2.3)
//   MODE 1 max:      a max filter (pmchss.json's optional mask max filter, section 2.2, runs
//                    inside the mask's dispatch instead)
//   MODE 2 min:      the min filter of the min-filter variant (section 2.3)
//   MODE 3 copy:     radius 0 (keeps a graph edge when a stage is switched off)
// Taps outside the texture are clamped to the edge.
#include "screen_pass.glsl"
layout(IMAGE_FORMAT, binding = 0) uniform writeonly image2D u_output;
uniform sampler2D u_input;
uniform ivec2 u_axis;    // (1, 0) horizontal, (0, 1) vertical
uniform int u_radius;    // texels
uniform float u_sigma;   // texels (gaussian)

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_output);
  if (any(greaterThanEqual(p, size))) return;
  float centre = texelFetch(u_input, p, 0).r;
#if MODE == 0
  float sum = 0.0;
  float weights = 0.0;
  for (int i = -u_radius; i <= u_radius; ++i) {
    ivec2 q = clamp(p + i * u_axis, ivec2(0), size - 1);
    float w = exp(-float(i * i) / (2.0 * u_sigma * u_sigma));
    sum += w * texelFetch(u_input, q, 0).r;
    weights += w;
  }
  float result = sum / weights;
#elif MODE == 1 || MODE == 2
  float result = centre;
  for (int i = -u_radius; i <= u_radius; ++i) {
    float v = texelFetch(u_input, clamp(p + i * u_axis, ivec2(0), size - 1), 0).r;
#if MODE == 1
    result = max(result, v);
#else
    result = min(result, v);
#endif
  }
#else
  float result = centre;
#endif
  imageStore(u_output, p, vec4(result));
}
