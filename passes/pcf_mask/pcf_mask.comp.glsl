#version 450 core
// Percentage-closer filtering (Reeves, Salesin & Cook 1987) with a fixed kernel in shadow-map
// texels. Kernel chosen at compile time (the pass picks the program variant per frame):
//   PCF_KERNEL_BOX   N x N taps one texel apart (box_size = N, odd), centred on the receiver;
//   PCF_KERNEL_VOGEL `samples` taps on a Vogel disk of `radius` texels, rotated per pixel by
//                    phi = 2 pi IGN(pixel) (Sterna 2018, section 1) so banding becomes noise.
// Each tap is a bilinear hardware comparison against the receiver plane (Isidoro
// 2006) minus a small constant bias.
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "sampling/sampling.glsl"
#include "shadow_taps.glsl"

layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2DShadow u_shadow_map;  // linear, clamp, depth compare (LEQUAL)
uniform float u_depth_bias;            // window depth
uniform int u_box_size;                // texels, odd
uniform int u_samples;                 // Vogel taps
uniform float u_radius;                // Vogel disk radius, texels

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  float lit = 1.0;
  Receiver r;
  if (shadow_receiver(u_depth, u_normal, p, r)) {
    vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));
    float sum = 0.0;
#if PCF_KERNEL_BOX
    int h = u_box_size / 2;
    for (int y = -h; y <= h; ++y)
      for (int x = -h; x <= h; ++x) sum += pcf_tap(u_shadow_map, r, vec2(x, y) * texel, u_depth_bias);
    lit = sum / float((2 * h + 1) * (2 * h + 1));
#else
    float phi = noise_rotation(vec2(p));
    for (int i = 0; i < u_samples; ++i) {
      vec2 o = vogel_disk_sample(i, u_samples, phi) * u_radius * texel;
      sum += pcf_tap(u_shadow_map, r, o, u_depth_bias);
    }
    lit = sum / float(u_samples);
#endif
  }
  if (self_shadowed(u_depth, u_normal, p)) lit = 0.0;
  imageStore(u_mask, p, vec4(lit));
}
