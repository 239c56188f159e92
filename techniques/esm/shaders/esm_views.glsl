// The extended shadow map's views (passes/esm_views.h): one face for directional and spot
// lights, six for a point light, two to four cascades, each a square tile of the map. Set by
// set_view_uniforms() (passes/esm_pass_common.h).
#include "common/light_faces.glsl"
uniform mat4 u_face_view_proj[6];  // world -> clip of each face
uniform vec4 u_face_rect[6];       // tile origin (texels) xy, tile side (texels) z; w: world size of
                                   // a texel (ortho), or of a texel at distance 1 (perspective)
uniform int u_face_count;          // 1, 2-4 cascades, or 6
uniform vec4 u_esm_light;          // homogeneous light: (position, 1), or (-direction, 0)
uniform int u_esm_ortho;           // 1: orthographic (directional)
uniform float u_esm_near;          // world units
uniform float u_esm_far;

// The face a world position is shadowed through: that of its direction from a point light
// (light_faces.glsl), the only face of one view (esm_face_of() on the CPU). Cascades: the mask
// pass picks them with shadow_common.glsl's cascade_of(), as the other techniques do.
int esm_face(vec3 world) { return u_face_count == 6 ? light_face(world - u_esm_light.xyz) : 0; }

// (x, y) in texels of the whole map (texel centres at +0.5) and z the window depth [0, 1] of a
// world position seen through face `face`; w = 1 inside the face's frustum, 0 outside.
vec4 esm_map_coord(int face, vec3 world) {
  vec4 clip = u_face_view_proj[face] * vec4(world, 1.0);
  if (clip.w <= 0.0) return vec4(0.0);
  vec3 ndc = clip.xyz / clip.w;
  bool inside = all(lessThanEqual(abs(ndc), vec3(1.0)));
  vec4 rect = u_face_rect[face];
  return vec4(rect.xy + (ndc.xy * 0.5 + 0.5) * rect.z, ndc.z * 0.5 + 0.5, inside ? 1.0 : 0.0);
}

// World-unit distance from the light of a window depth (along the view axis).
float esm_light_distance(float window_depth) {
  if (u_esm_ortho == 1) return u_esm_near + window_depth * (u_esm_far - u_esm_near);
  float z = window_depth * 2.0 - 1.0;
  return 2.0 * u_esm_near * u_esm_far / (u_esm_far + u_esm_near - z * (u_esm_far - u_esm_near));
}

// A receiver's window depth moved `bias` towards the light. The bias is in window depth units; a
// point light's faces have their near plane at 1e-3 of the far one, where a window-depth step at
// the far end is 1000x one at the near end (2e-4 would be 0.3 m at 3 m): there it means that
// fraction of the depth range, (far - near) x bias, at any distance.
float esm_biased_depth(float window_depth, float bias) {
  if (u_face_count != 6) return window_depth - bias;  // one view or cascades: a window-depth bias
  float d = esm_light_distance(window_depth) - bias * (u_esm_far - u_esm_near);
  float n = u_esm_near, f = u_esm_far;
  float ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * max(d, n));
  return ndc * 0.5 + 0.5;
}

// World size of one texel of face `face` at light distance d.
float esm_texel_world(int face, float d) {
  float scale = u_face_rect[face].w;
  return u_esm_ortho == 1 ? scale : d * scale;
}
