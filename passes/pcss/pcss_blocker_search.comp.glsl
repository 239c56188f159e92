#version 450 core
// PCSS step 1, blocker search (Fernando 2005, section 3 step 1): average the light distance of
// the shadow-map texels nearer to the light than the receiver, within the region of the map
// that can hold occluders of the receiver.
//
// Search width (shadow-map UV): the penumbra a blocker at the shadow frustum's near plane (the
// farthest a blocker can be from the receiver) would cast, blocker_search_width_uv(d_r) in
// shadow_common.glsl, by similar triangles (Fernando 2005; NVIDIA's PCSS sample writes it
// LIGHT_SIZE_UV * (z_r - near) / z_r for a spot light). d_r is the receiver's distance from
// the emitter plane (directional) or light position (spot), world units.
//
// Output: mean blocker distance from the light in world units, 0 where no blocker was found
// (fully lit, background, or outside the shadow map) and where the receiver faces away from the
// light (the filter writes 0 there whatever the blockers). Taps: `samples` Vogel-disk positions
// rotated per receiver by 2 pi IGN (tap_rotation), each a textureGather of 4 raw depths (so
// 4 x samples texels), each compared against the receiver plane (Isidoro 2006) minus a constant
// bias.
// A point light's six faces: taps placed by direction (shadow_tap), distances from the light
// along each tap's ray, so the search runs on across face edges.
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "sampling/sampling.glsl"
#include "pcf_mask/shadow_taps.glsl"

layout(r32f, binding = 0) uniform writeonly image2D u_blocker;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_shadow_map;   // raw depth: nearest, no comparison
uniform float u_depth_bias;       // window depth
uniform int u_samples;
uniform float u_light_size_scale; // multiplies the light's size (unitless; widths are linear in it)
uniform float u_max_search_uv;    // clamp of the search width, shadow-map UV

void main() {
  ivec2 p = screen_pixel();
  if (any(greaterThanEqual(p, imageSize(u_blocker)))) return;
  float mean_blocker = 0.0;
  Receiver r;
  if (receiver_at(u_depth, u_normal, p, r) == RECEIVER_FILTERED) {
    add_receiver_plane(u_depth, p, r);
    float d_r = receiver_light_distance(r);
    float width = min(blocker_search_width_uv(d_r) * u_light_size_scale, u_max_search_uv);
    float radius = 0.5 * width;
    float phi = tap_rotation(r, vec2(p));
    float sum = 0.0;
    int count = 0;
    for (int i = 0; i < u_samples; ++i) {
      vec2 o = vogel_disk_sample(i, u_samples, phi) * radius;
      ShadowTap t = shadow_tap(r, o, u_depth_bias);
      vec4 depths = textureGather(u_shadow_map, t.uv, 0);
      for (int k = 0; k < 4; ++k)
        if (depths[k] < t.ref) {
          sum += light_distance(depths[k]) * t.distance_scale;
          ++count;
        }
    }
    if (count > 0) mean_blocker = sum / float(count);
  }
  imageStore(u_blocker, p, vec4(mean_blocker));
}
