#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Raster reference, one light sample: adds the hard visibility of every receiver pixel as seen
// from one sample point of the emitter disk (1 = the point sees the receiver) to the running sum.
// One depth comparison per pixel at the nearest texel of that point's perspective depth map
// (sample_point_view.h).
// Same light model as the ray tracer (raytraced_reference.h): a sample point behind the receiver's
// tangent plane is hidden by the receiver's own surface; otherwise the receiver, lifted by the ray
// tracer's normal offset, is compared with the map.
// Bias against acne: the receiver moves TOWARDS the sample point (along the shadow ray, so the
// shadow's edges do not move, unlike a normal offset, which shifts them by offset / tan(elevation)
// on a grazing-lit ground) by `u_texel_offset` texel footprints x tan(angle between normal and
// ray): the depth a receiver-plane slope gains over the distance between the receiver and the
// nearest texel centre (receiver-plane depth bias, Isidoro 2006, in world units). Flat-facing
// receivers get almost none, grazing ones up to 10 texels.
//
// A point light's sample (SIX_FACES) is a point light of its own inside the scene: its map holds
// six faces (scene/light_faces.h), read through shadow_common.glsl's face_shadow_coord(), with
// u_light_pos at the sample point; the depth is linear along the face's axis.
#include "screen_pass.glsl"
#ifdef SIX_FACES
#include "common/shadow_common.glsl"
#endif
layout(r32f, binding = 0) uniform image2D u_accumulation;  // sum of visibilities so far
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform sampler2D u_normal;    // gbuffer_normal: octahedral
uniform sampler2D u_sample_map;   // DEPTH32F window depth from the sample point (SIX_FACES: linear)
uniform mat4 u_sample_view_proj;  // world -> the sample map's clip space
uniform int u_sample_is_point;    // 1: point sample (perspective map), 0: parallel (orthographic)
uniform vec3 u_sample_point;      // point samples: the map's eye, world units
uniform vec3 u_sample_dir;        // unit, light -> scene: the map's view axis
uniform float u_normal_offset;    // world units (the ray tracer's shadow-ray offset)
uniform float u_texel_offset;     // texel footprints (the `receiver_bias` parameter)
uniform float u_texel_tan;        // perspective: frustum (SIX_FACES: face) width at distance 1 / its texels
uniform float u_texel_world;      // orthographic: map width / map size, world units

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_accumulation)))) return;
  vec4 pos = gbuffer_position(u_depth, p);
  if (pos.w <= 0.0) return;
  vec3 n = gbuffer_normal(u_normal, p);
  vec3 to_light = -u_sample_dir;  // parallel sample: the same direction for every receiver
  float depth = 0.0;             // along the map's axis from a point sample, world units
  if (u_sample_is_point == 1) {
    to_light = normalize(u_sample_point - pos.xyz);
#ifdef SIX_FACES
    vec3 a = abs(pos.xyz - u_sample_point);
    depth = max(a.x, max(a.y, a.z));  // along the axis of the face it falls in
#else
    depth = max(dot(pos.xyz - u_sample_point, u_sample_dir), 0.0);
#endif
  }
  float cos_theta = dot(n, to_light);
  float texel_world = depth * u_texel_tan + u_texel_world;
  float tan_theta = min(sqrt(max(1.0 - cos_theta * cos_theta, 0.0)) / max(cos_theta, 1e-4), 10.0);
  vec3 x = pos.xyz + u_normal_offset * n + (u_texel_offset * texel_world * tan_theta) * to_light;
  float lit = 1.0;  // outside the map (or behind the eye): nothing of the scene blocks it
#ifdef SIX_FACES
  int face = light_face(x - u_sample_point);
  vec3 c = face_shadow_coord(face, x);  // map uv and linear depth
  if (cos_theta <= 0.0) {
    lit = 0.0;
  } else if (c.z >= 0.0) {
    // A texel of the receiver's own face: its tile holds every direction of that face with a
    // guard band around it (kFaceGuardTexels), so the nearest texel is never another face's.
    vec4 rect = u_light_face_rect[face] * vec4(textureSize(u_sample_map, 0).xxx, 1.0);
    ivec2 t = clamp(ivec2(c.xy * vec2(textureSize(u_sample_map, 0))), ivec2(rect.xy), ivec2(rect.xy + rect.z) - 1);
    lit = min(c.z, 1.0) <= texelFetch(u_sample_map, t, 0).r ? 1.0 : 0.0;
  }
#else
  vec4 clip = u_sample_view_proj * vec4(x, 1.0);
  if (cos_theta <= 0.0) {
    lit = 0.0;  // behind the receiver's tangent plane: its own surface hides the point
  } else if (clip.w > 0.0) {
    vec3 c = clip.xyz / clip.w * 0.5 + 0.5;
    if (all(greaterThanEqual(c, vec3(0.0))) && all(lessThanEqual(c, vec3(1.0)))) {
      ivec2 size = textureSize(u_sample_map, 0);
      ivec2 t = clamp(ivec2(c.xy * vec2(size)), ivec2(0), size - 1);
      lit = c.z <= texelFetch(u_sample_map, t, 0).r ? 1.0 : 0.0;
    }
  }
#endif
  imageStore(u_accumulation, p, imageLoad(u_accumulation, p) + vec4(lit, 0.0, 0.0, 0.0));
}
