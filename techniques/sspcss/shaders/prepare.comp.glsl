#version 450 core
// Preparation (section 1): the hard shadow map in screen space and the projected shadow map, in
// one texel per pixel so each tap of the later passes is one fetch:
//   r  hard visibility: 1 lit, 0 in shadow; one bilinear hardware comparison (the 2x2 texels
//      around the receiver, against its plane: passes/pcf_mask/shadow_taps.glsl), so the step
//      falls between texels instead of on a texel grid
//   g  projected shadow map: where r < 1, the light distance of the blockers read from the
//      shadow map at the pixel (world units, light_distance(): the mean of the 2x2 texels
//      nearer the light than the receiver); 0 where lit
//   b  linear view depth of the receiver (world units; 0 = background), the range term's input
//   a  1 where the receiver faces away from the light (in its own shadow, mask 0), else 0
// Background pixels and pixels outside the light frustum are lit. No NDC depth leaves this pass:
// the shadow map's window depth is turned into a light distance here.
layout(local_size_x = 8, local_size_y = 8) in;
#include "shadow_common.glsl"
#include "../../../passes/pcf_mask/shadow_taps.glsl"

layout(rgba32f, binding = 0) uniform writeonly image2D u_projected;
uniform sampler2D u_position;          // world position, w = linear view depth
uniform sampler2D u_normal;            // world-space unit normal
uniform sampler2D u_shadow_map;        // raw window depth, nearest
uniform sampler2DShadow u_shadow_cmp;  // the same texture: linear, depth comparison
uniform float u_depth_bias;            // window depth

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_projected)))) return;
  vec4 pos = texelFetch(u_position, p, 0);
  if (pos.w <= 0.0) {
    imageStore(u_projected, p, vec4(1.0, 0.0, 0.0, 0.0));
    return;
  }
  float visibility = 1.0;
  float blocker = 0.0;  // light distance of the blockers, where visibility < 1
  Receiver r;
  if (shadow_receiver(u_position, u_normal, p, r)) {
    visibility = pcf_tap(u_shadow_cmp, r, vec2(0.0), u_depth_bias);
    if (visibility < 1.0) {
      vec4 stored = textureGather(u_shadow_map, r.coord.xy, 0);
      float limit = receiver_depth_at(r, vec2(0.0), u_depth_bias);
      float sum = 0.0, count = 0.0;
      for (int k = 0; k < 4; ++k)
        if (stored[k] < limit) {
          sum += light_distance(stored[k]);
          count += 1.0;
        }
      // The filtered comparison and the gather can disagree by rounding at a texel's edge:
      // then the receiver itself is the blocker (a contact, no penumbra).
      blocker = count > 0.0 ? sum / count : light_distance(r.coord.z);
    }
  }
  bool self_shadowed = faces_away_from_light(pos.xyz, texelFetch(u_normal, p, 0).xyz);
  if (self_shadowed) {
    // Its own surface blocks the light: distance 0 from the receiver when the map has nothing
    // nearer (a contact, no penumbra).
    if (visibility == 1.0) blocker = light_distance(clamp(shadow_coord(pos.xyz).z, 0.0, 1.0));
    visibility = 0.0;
  }
  imageStore(u_projected, p, vec4(visibility, blocker, pos.w, self_shadowed ? 1.0 : 0.0));
}
