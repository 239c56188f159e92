#version 450 core
// Percentage-closer filtering (Reeves, Salesin & Cook 1987) with a fixed kernel in shadow-map
// texels. Kernel chosen at compile time (the pass picks the program variant per frame):
//   PCF_KERNEL_BOX   N x N taps one texel apart (box_size = N, odd), centred on the receiver:
//                    N x N bilinear taps cover (N + 1)^2 texels with separable weights
//                    (1 - f, 1, ..., 1, f), so they are read as ((N + 1) / 2)^2 compared
//                    textureGathers of 2 x 2 texels each (9 instead of 25 fetches at N = 5), the
//                    weights applied here;
//   PCF_KERNEL_VOGEL `samples` taps on a Vogel disk of `radius` texels, rotated per receiver by
//                    phi = 2 pi IGN (Sterna 2018, section 1) so banding becomes noise; IGN of
//                    the receiver's place in the map or of the pixel (tap_rotation,
//                    receiver_plane.glsl).
// Each tap is a bilinear hardware comparison against the receiver plane (Isidoro
// 2006) minus a small constant bias. A point light's six faces (shadow_common.glsl) place every
// tap by direction (shadow_tap), the box kernel included.
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
  ivec2 p = screen_pixel();
  if (any(greaterThanEqual(p, imageSize(u_mask)))) return;
  Receiver r;
  int kind = receiver_at(u_depth, u_normal, p, r);
  float lit = kind == RECEIVER_FACES_AWAY ? 0.0 : 1.0;  // no taps needed for those two kinds
  if (kind == RECEIVER_FILTERED) {
    add_receiver_plane(u_depth, p, r);
    vec2 size = vec2(textureSize(u_shadow_map, 0));
    float sum = 0.0;
#if PCF_KERNEL_BOX
    if (kTiledMap) {
      // Six faces or cascades: the same N x N bilinear taps one texel apart, each placed by
      // shadow_tap (by its own direction, or kept in the cascade's tile), since a gather's 2 x 2
      // block may straddle two tiles.
      int h = u_box_size / 2;
      for (int y = -h; y <= h; ++y)
        for (int x = -h; x <= h; ++x) sum += pcf_tap(u_shadow_map, r, vec2(x, y) * u_shadow_texel, u_depth_bias);
      lit = sum / float(u_box_size * u_box_size);
    } else {
      int h = u_box_size / 2;
      float total = 0.0;
      vec2 t = r.coord.xy * size - 0.5;  // texel space, texel centres at integers
      vec2 base = floor(t);
      vec2 f = t - base;                 // the bilinear fraction every tap shares
      for (int by = -h; by <= h; by += 2) {
        vec2 wy = vec2(by == h ? f.y : 1.0, by == -h ? 1.0 - f.y : 1.0);  // rows by + 1, by
        for (int bx = -h; bx <= h; bx += 2) {
          vec2 wx = vec2(bx == -h ? 1.0 - f.x : 1.0, bx == h ? f.x : 1.0);  // columns bx, bx + 1
          vec2 corner = (base + vec2(bx, by) + 1.0) / size;  // between the block's 4 texel centres
          // textureGather order: (bx, by+1), (bx+1, by+1), (bx+1, by), (bx, by)
          vec4 passed = textureGather(u_shadow_map, corner, receiver_depth_at(r, corner - r.coord.xy, u_depth_bias));
          vec4 w = vec4(wx.x * wy.x, wx.y * wy.x, wx.y * wy.y, wx.x * wy.y);
          sum += dot(passed, w);
          total += dot(vec4(1.0), w);  // N^2 up to rounding; the same sum when every texel passes
        }
      }
      lit = sum / total;  // exactly 1 where all pass, 0 where none does
    }
#else
    vec2 texel = kLightFaces == 1 ? 1.0 / size : vec2(u_shadow_texel);  // six faces: one face texel
    float phi = tap_rotation(r, vec2(p));
    for (int i = 0; i < u_samples; ++i) {
      vec2 o = vogel_disk_sample(i, u_samples, phi) * u_radius * texel;
      sum += pcf_tap(u_shadow_map, r, o, u_depth_bias);
    }
    lit = sum / float(u_samples);
#endif
  }
  imageStore(u_mask, p, vec4(lit));
}
