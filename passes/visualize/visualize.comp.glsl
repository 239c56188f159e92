#version 450 core
// Any single-channel texture -> RGBA8 for viewing: value v (DEPTH32F optionally linearised
// from window depth to view distance with near/far, world units) is mapped to
// t = clamp((v - min) / (max - min), 0, 1), then to grey (t, t, t) or a heat ramp
// (blue, cyan, green, yellow, red at t = 0, .25, .5, .75, 1). The input is read nearest at the
// output pixel's relative position, so sizes may differ (e.g. a shadow map shown on screen).
#include "screen_pass.glsl"
layout(rgba8, binding = 0) uniform writeonly image2D u_output;
uniform sampler2D u_input;
uniform float u_min;
uniform float u_max;
uniform int u_heat;             // 0 grey, 1 heat
uniform int u_linearize_depth;  // 1: perspective window depth -> distance
uniform float u_near;           // world units
uniform float u_far;

vec3 heat(float t) {
  const vec3 stops[5] = vec3[5](vec3(0, 0, 1), vec3(0, 1, 1), vec3(0, 1, 0), vec3(1, 1, 0), vec3(1, 0, 0));
  float x = t * 4.0;
  int i = min(int(x), 3);
  return mix(stops[i], stops[i + 1], x - float(i));
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 out_size = imageSize(u_output);
  if (any(greaterThanEqual(p, out_size))) return;
  ivec2 in_size = textureSize(u_input, 0);
  ivec2 q = min((p * in_size) / out_size, in_size - 1);
  float v = texelFetch(u_input, q, 0).r;
  if (u_linearize_depth == 1) {
    float z = v * 2.0 - 1.0;
    v = 2.0 * u_near * u_far / (u_far + u_near - z * (u_far - u_near));
  }
  float span = u_max - u_min;
  float t = span != 0.0 ? clamp((v - u_min) / span, 0.0, 1.0) : 0.0;
  vec3 c = u_heat == 1 ? heat(t) : vec3(t);
  imageStore(u_output, p, vec4(c, 1.0));
}
