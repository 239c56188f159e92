// Shadow-map filtering helpers shared by the PCF and PCSS passes: the receiver (its plane,
// passes/common/receiver_plane.glsl) and one hardware-compared tap.
// Needs: common/shadow_common.glsl included before.
#include "common/receiver_plane.glsl"

// One hardware-compared tap (placed by shadow_tap): a sampler2DShadow with GL_LINEAR +
// GL_COMPARE_REF_TO_TEXTURE returns the bilinear weight of the 2x2 texels that pass (bilinear
// PCF), 1 = lit.
float pcf_tap(sampler2DShadow map, Receiver r, vec2 offset_uv, float bias) {
  ShadowTap t = shadow_tap(r, offset_uv, bias);
  return texture(map, vec3(t.uv, t.ref));
}
