#version 450 core
// Penumbra mask (Sterna 2018, section 2.2): the blocker search of Listing 3 run at a reduced
// resolution (screen/4 or screen/2), one texel per invocation. The texel's receiver is the
// G-buffer position at the centre of the full-resolution block it covers.
//
// OUTPUT_BLOCKER_DEPTH (define) turns the same search into the debug view of the average
// blocker window depth (1 = no blocker) instead of the penumbra.
layout(local_size_x = 8, local_size_y = 8) in;
#include "shadow_common.glsl"
#include "noise.glsl"
#include "receiver_plane.glsl"
#include "pmchss_common.glsl"

layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_position;    // full resolution, w = linear view depth (0: background)
uniform sampler2D u_shadow_map;  // raw window depth, nearest (Listing 3's pointClampSampler)
uniform int u_default_one;       // section 2.2: write 1 instead of 0 where no blocker is found

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 mask_size = imageSize(u_mask);
  if (any(greaterThanEqual(p, mask_size))) return;
  ivec2 full_size = textureSize(u_position, 0);
  ivec2 scale = max(full_size / mask_size, ivec2(1));
  ivec2 full = min(p * scale + scale / 2, full_size - 1);

  // "Lit" everywhere nothing is found: background, outside the light frustum, no blocker.
  float no_blocker = u_default_one == 1 ? 1.0 : 0.0;
#ifdef OUTPUT_BLOCKER_DEPTH
  no_blocker = 1.0;
#endif
  float value = no_blocker;
  vec4 pos = texelFetch(u_position, full, 0);
  if (pos.w > 0.0) {
    vec3 c = shadow_coord(pos.xyz);
    if (pmchss_in_shadow_frustum(c)) {
      vec2 dz_duv = receiver_plane_gradient(u_position, full, c, vec3(0.0));
      // Noise on the mask's own pixel grid: neighbouring mask texels get different rotations.
      float phi = pmchss_noise_phi(p, false);
      float blocker;
      float count = pmchss_blocker_search(u_shadow_map, c.xy, c.z, dz_duv, BLOCKER_SAMPLES, phi,
                                          blocker);
#ifdef OUTPUT_BLOCKER_DEPTH
      value = blocker;
#else
      if (count > 0.0) value = pmchss_penumbra_from_blocker(c.z, blocker);
#endif
    }
  }
  imageStore(u_mask, p, vec4(value));
}
