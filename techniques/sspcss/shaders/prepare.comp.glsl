#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Preparation (section 1): the hard shadow map in screen space and the projected shadow map, in
// one texel per pixel so each tap of the later passes is one fetch:
//   r  hard visibility: 1 lit, 0 in shadow. The mean of four sub-pixel samples (a 2x2 grid on
//      the receiver's tangent plane), each a bilinear hardware comparison against the receiver
//      plane (passes/pcf_mask/shadow_taps.glsl): a hard shadow anti-aliased over the pixel, so a
//      shadow thinner than a pixel is still there for the search and the filter to find.
//      u_subpixel = 0: one such sample at the pixel centre (4x fewer shadow-map reads)
//   g  projected shadow map: where r < 1, the light distance of the blockers read from the
//      shadow map at the pixel (world units, light_distance(): the mean of the texels nearer
//      the light than the receiver among the samples' 2x2 footprints); 0 where lit
//   b  linear view depth of the receiver (world units; 0 = background), the range term's input
//   a  1 where the receiver faces away from the light (in its own shadow, mask 0), else 0
// Background pixels and pixels outside the light frustum are lit. No NDC depth leaves this pass:
// the shadow map's window depth is turned into a light distance here (a point light's six faces:
// along the ray from the light, every sample placed by direction through shadow_tap()).
#include "screen_pass.glsl"
#include "common/shadow_common.glsl"
#include "pcf_mask/shadow_taps.glsl"
#include "screen_geometry.glsl"

layout(rgba16f, binding = 0) uniform writeonly image2D u_projected;
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_shadow_map;        // raw window depth, nearest
uniform sampler2DShadow u_shadow_cmp;  // the same texture: linear, depth comparison
uniform float u_depth_bias;            // window depth
uniform mat4 u_view_inverse;           // view space -> world
uniform int u_subpixel;                // 1: 2x2 sub-pixel samples, 0: the pixel centre only

// The four sub-pixel samples of the pixel's footprint (a 2x2 grid, pixels).
const vec2 kSubPixel[4] = vec2[](vec2(-0.25, -0.25), vec2(0.25, -0.25), vec2(-0.25, 0.25), vec2(0.25, 0.25));
// Below this |cos| between the view ray and the receiver's normal (~75 degrees from face-on) the
// samples stay at the pixel centre. Measured on the built-in scenes at 640x360: 0.1 lets the
// silhouettes of the ball and the columns pick up the plane's far points (RMSE on ball 0.0091
// instead of 0.0066), 0.5 gives up footprints that help (penumbra RMSE on colonnade 0.116
// instead of 0.103).
const float kGrazingCos = 0.25;

// Shadow-map uv offset from the receiver of the point of its tangent plane seen through the
// pixel position `pixel` (view space: the plane is n . X = plane).
vec2 tangent_plane_offset(vec2 pixel, vec3 n_view, float plane, float depth, Receiver r) {
  vec3 ray = view_ray(pixel);
  float n_dot_ray = dot(n_view, ray);
  float t = n_dot_ray * plane > 0.0 ? plane / n_dot_ray : depth;
  t = clamp(t, 0.5 * depth, 2.0 * depth);  // never far from the pixel's own depth
  vec3 world = (u_view_inverse * vec4(t * ray, 1.0)).xyz;
  return shadow_offset_to(r, world);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_projected)))) return;
  vec4 pos = gbuffer_position(u_depth, p);
  if (pos.w <= 0.0) {
    imageStore(u_projected, p, vec4(1.0, 0.0, 0.0, 0.0));
    return;
  }
  vec3 normal = gbuffer_normal(u_normal, p);
  float visibility = 1.0;
  float blocker = 0.0;  // light distance of the blockers, where visibility < 1
  Receiver r;
  if (shadow_receiver(u_depth, u_normal, p, r)) {
    vec3 n_view = normalize(mat3(u_view) * normal);
    vec3 centre_ray = view_ray(vec2(p));
    float plane = pos.w * dot(n_view, centre_ray);
    // Seen at a grazing angle (a silhouette, mostly) the plane is no guide to the surface a
    // quarter pixel away: sample the centre four times.
    float spread = abs(dot(n_view, centre_ray)) > kGrazingCos * length(centre_ray) ? 1.0 : 0.0;
    int samples = u_subpixel == 1 ? 4 : 1;
    if (samples == 1) spread = 0.0;
    visibility = 0.0;
    float sum = 0.0, count = 0.0;
    for (int i = 0; i < samples; ++i) {
      vec2 offset = tangent_plane_offset(vec2(p) + spread * kSubPixel[i], n_view, plane, pos.w, r);
      float v = pcf_tap(u_shadow_cmp, r, offset, u_depth_bias);
      visibility += v / float(samples);
      if (v == 1.0) continue;
      ShadowTap tap = shadow_tap(r, offset, u_depth_bias);
      vec4 stored = textureGather(u_shadow_map, tap.uv, 0);  // the tap's 2x2 texels
      for (int k = 0; k < 4; ++k)
        if (stored[k] < tap.ref) {
          sum += light_distance(stored[k]) * tap.distance_scale;
          count += 1.0;
        }
    }
    // The filtered comparison and the gather can disagree by rounding at a texel's edge:
    // then the receiver itself is the blocker (a contact, no penumbra).
    if (visibility < 1.0) blocker = count > 0.0 ? sum / count : receiver_light_distance(r);
  }
  bool self_shadowed = faces_away_from_light(pos.xyz, normal);
  if (self_shadowed) {
    // Its own surface blocks the light: distance 0 from the receiver when the map has nothing
    // nearer (a contact, no penumbra).
    if (visibility == 1.0)
      blocker = light_distance(clamp(shadow_coord(pos.xyz).z, 0.0, 1.0)) * axis_to_ray_scale(pos.xyz);
    visibility = 0.0;
  }
  imageStore(u_projected, p, vec4(visibility, blocker, pos.w, self_shadowed ? 1.0 : 0.0));
}
