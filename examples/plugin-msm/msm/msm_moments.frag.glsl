#version 450 core
// msm_moments: the moments (z, z^2, z^3, z^4) of the caster's light window depth z in [0, 1],
// written through the optimised quantisation (Peters & Klein 2015, "Moment Shadow Mapping",
// the 16-bit variant; msm_quantization.h holds the transform), so they fit 16-bit UNORM.
#include "shadow_map/caster_material.glsl"
layout(location = 0) out vec4 o_moments;
uniform mat4 u_to_optimised;
uniform vec4 u_optimised_offset;

void main() {
  discard_uncovered();
  float z = gl_FragCoord.z;
  float z2 = z * z;
  o_moments = u_to_optimised * vec4(z, z2, z2 * z, z2 * z2) + u_optimised_offset;
}
