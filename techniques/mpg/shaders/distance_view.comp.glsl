#version 450 core
// Debug view of D, the paper's tuning aid (section 3.1: "draw the occluder distance into the
// scene via a color gradient ... to ensure a proper progression of penumbra scale"):
//   D > 0        heat ramp of D / D_max (blue, cyan, green, yellow, red), D_max = max_kernel for
//                the PCF and Gaussian alterations, max_passes for the multi-pass one
//   lit, D = 0   light grey
//   shadowed, D = 0  dark grey (contact, the receiver's own umbra, or frozen by the early-out)
//   background   black
// It reads the distance map as pass 4 receives it (after the early-out and the dilation).
#include "screen_pass.glsl"

layout(rgba8, binding = 0) uniform writeonly image2D u_output;
uniform sampler2D u_distance_map;  // texelFetch
uniform float u_max_control;       // D_max

vec3 heat(float t) {
  const vec3 stops[5] = vec3[5](vec3(0, 0, 1), vec3(0, 1, 1), vec3(0, 1, 0), vec3(1, 1, 0), vec3(1, 0, 0));
  float x = clamp(t, 0.0, 1.0) * 4.0;
  int i = min(int(x), 3);
  return mix(stops[i], stops[i + 1], x - float(i));
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_output)))) return;
  vec4 v = texelFetch(u_distance_map, p, 0);
  vec3 c = vec3(0.0);
  if (v.b > 0.0) c = v.g > 0.0 ? heat(v.g / u_max_control) : vec3(v.r > 0.5 ? 0.3 : 0.85);
  imageStore(u_output, p, vec4(c, 1.0));
}
