// Light-space helpers shared by every pass that reads a shadow map. The C++ side sets these
// uniforms with set_shadow_uniforms() (passes/common/shadow_uniforms.h).
//
// The map holds one view of the light (kLightFaces = 1: directional, spot, a point light
// outside the scene) or the six faces of a point light inside the scene (kLightFaces = 6,
// scene/light_faces.h), each a tile of the map seen through its own perspective frustum; then
// near/far are every face's planes, a depth is the distance along the face's axis, linear
// between them as a directional light's is (shadow_map.frag.glsl says why), u_light_frustum_width
// is a face's and u_shadow_texel one texel of a face in face UV.
#include "light_faces.glsl"
// Six faces are a compile-time variant: PassContext::program() defines SIX_FACES for a frame
// whose light needs them, so a one-view frame runs none of their code. With the choice made at
// run time (a uniform) the one-view filters took 8-16 % longer in the results suite (H100);
// compiled apart, their time is that of the commit before six faces (docs/techniques.md).
#ifdef SIX_FACES
const int kLightFaces = 6;
#else
const int kLightFaces = 1;
#endif
// Cascades (scene/cascades.h) are a compile-time variant too: PassContext::program() defines
// CASCADES as their count for a frame that has more than one. Each is a tile of the map with an
// orthographic view of its own; all share the scene map's light view and depth range, so a depth
// means one distance everywhere and only the width of a texel changes between cascades.
#ifdef CASCADES
const int kCascades = CASCADES;
#else
const int kCascades = 1;
#endif
// The map is tiles (six faces or cascades): every read of it goes through shadow_tap().
const bool kTiledMap = kLightFaces != 1 || kCascades != 1;
uniform mat4 u_cascade_view_proj[4];  // cascades: world -> clip of each
uniform vec4 u_cascade_rect[4];       // cascades: tile origin (xy) and side (z), map UV; w: its width, world units
uniform float u_cascade_margin;       // cascades: scene::kCascadeMargin, as a fraction of a square's half side
uniform float u_cascade_blend;        // cascades: the blend band, as a fraction of a square's half side
uniform mat4 u_light_face_view_proj[6];  // six faces: world -> clip of each face
uniform vec4 u_light_face_rect[6];       // six faces: tile origin (xy) and side (z), map UV
uniform mat4 u_light_view_proj;   // world -> light clip space
uniform mat4 u_light_view;        // world -> light view space (looking down -Z)
uniform float u_light_near;       // world units from the emitter plane / light position
uniform float u_light_far;
uniform int u_light_ortho;        // 1: directional (orthographic map), 0: spot or point (perspective)
uniform float u_light_size_world; // emitter disk diameter, world units (Light::size)
uniform float u_light_frustum_width; // ortho: frustum width in world units; spot: width of the
                                     // frustum at distance 1 (2 tan(fov/2))
uniform vec3 u_light_dir;         // unit, light -> scene
uniform vec3 u_light_pos;         // emitter centre
uniform float u_shadow_texel;     // one shadow-map texel in UV (1 / shadow-map size)
uniform float u_light_emitter_distance; // directional: emitter plane to scene centre, world
                                        // units (scene::emitter_distance); angular diameter
                                        // of the sun-like emitter = size / this
uniform float u_blocker_height_scale; // the scene's height along the light's rays, world units
                                      // (scene::blocker_height_scale; 1 without a scene)

// (map uv, depth) of a world position seen through face `face` of six, the depth linear in the
// distance along the face's axis (clip w); outside [0, 1] at the light itself.
vec3 face_shadow_coord(int face, vec3 world) {
  vec4 clip = u_light_face_view_proj[face] * vec4(world, 1.0);
  if (clip.w <= 0.0) return vec3(-1.0);
  vec2 ndc = clip.xy / clip.w;
  vec4 rect = u_light_face_rect[face];
  return vec3(rect.xy + (ndc * 0.5 + 0.5) * rect.z, (clip.w - u_light_near) / (u_light_far - u_light_near));
}

// The cascade an invocation reads: that of the first point it looks up (its receiver), so the
// receiver's neighbours and taps are all read in the receiver's cascade.
int g_cascade = -1;

// A hash in [0, 1) of the cell holding a world position: cubes one texel of the finest cascade
// wide, in the light's view. A point gets the same value in every pass and, though the G-buffer
// places it a little differently as the camera moves, in every frame: a hash of its exact bits
// redrew the cascade of every point in the blend band each frame (flicker under a pan:
// docs/results/cascades.md, "Temporal stability").
float position_hash(vec3 world) {
  float texel = u_cascade_rect[0].w * u_shadow_texel / u_cascade_rect[0].z;  // world units
  uvec3 u = uvec3(ivec3(floor((u_light_view * vec4(world, 1.0)).xyz / texel)));
  uint h = u.x * 0x8da6b343u ^ u.y * 0xd8163841u ^ u.z * 0xcb1ab31fu;
  h ^= h >> 16; h *= 0x7feb352du; h ^= h >> 15; h *= 0x846ca68bu; h ^= h >> 16;
  return float(h >> 8) * (1.0 / 16777216.0);
}

// The first cascade whose square holds `world` at least the margin inside its edge (room for a
// filter kernel); within the blend band beyond, the next cascade for a share of the points that
// grows towards the margin (a dithered blend: scene/cascades.h). kCascades: none holds it.
int cascade_of(vec3 world) {
  float jitter = position_hash(world);
  for (int i = 0; i < kCascades; ++i) {
    vec4 clip = u_cascade_view_proj[i] * vec4(world, 1.0);
    float edge = max(abs(clip.x), abs(clip.y));   // 1 at the square's edge (orthographic: w = 1)
    float held = 1.0 - u_cascade_margin;          // inside this: held with room for a kernel
    if (i == kCascades - 1) return edge <= 1.0 ? i : kCascades;
    if (edge <= held - u_cascade_blend) return i;
    if (edge <= held && jitter * u_cascade_blend < held - edge) return i;
  }
  return kCascades;
}

// The width of the light's frustum in the sense of u_light_frustum_width, for the invocation's
// cascade: its square's world width over its side in map UV, so a world size / this is map UV.
float light_frustum_width() {
  if (kCascades == 1) return u_light_frustum_width;
  vec4 rect = u_cascade_rect[max(g_cascade, 0)];
  return rect.w / rect.z;
}

// (shadow-map uv in [0,1], window depth in [0,1]) of a world position: six faces, through the
// face of its direction from the light; cascades, through the invocation's cascade (outside the
// map when no cascade holds its receiver).
vec3 shadow_coord(vec3 world) {
  if (kLightFaces == 6) return face_shadow_coord(light_face(world - u_light_pos), world);
  if (kCascades != 1) {
    if (g_cascade < 0) g_cascade = cascade_of(world);
    if (g_cascade >= kCascades) return vec3(-1.0);
    vec3 ndc = (u_cascade_view_proj[g_cascade] * vec4(world, 1.0)).xyz;
    vec4 rect = u_cascade_rect[g_cascade];
    return vec3(rect.xy + (ndc.xy * 0.5 + 0.5) * rect.z, ndc.z * 0.5 + 0.5);
  }
  vec4 clip = u_light_view_proj * vec4(world, 1.0);
  vec3 ndc = clip.xyz / clip.w;
  return ndc * 0.5 + 0.5;
}

// World-unit distance from the light (emitter plane for directional, light position along the
// axis for spot and for each of six faces) of a window depth read from the shadow map.
float light_distance(float window_depth) {
  float z = window_depth * 2.0 - 1.0;
  if (u_light_ortho == 1 || kLightFaces != 1) return u_light_near + window_depth * (u_light_far - u_light_near);
  return 2.0 * u_light_near * u_light_far / (u_light_far + u_light_near - z * (u_light_far - u_light_near));
}

// A unit direction's tangent basis: the same as scene::emitter_basis (scene/light.cpp).
void direction_basis(vec3 d, out vec3 tangent, out vec3 bitangent) {
  vec3 helper = abs(d.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  tangent = normalize(cross(helper, d));
  bitangent = cross(d, tangent);
}

// A distance from the light along the view's axis (light_distance() of a depth read through
// shadow_coord(world)) times this is the distance along the ray to `world`: 1 for one view; for
// six faces, 1 / the major component of the unit direction (a face's depth is along its axis).
// For a unit direction from the light: 1 / its major component.
float axis_to_ray_scale_of(vec3 unit_direction) {
  vec3 a = abs(unit_direction);
  return 1.0 / max(max(a.x, a.y), a.z);
}
float axis_to_ray_scale(vec3 world) {
  return kLightFaces == 1 ? 1.0 : axis_to_ray_scale_of(normalize(world - u_light_pos));
}

// Distance from the light (world units) of a world position in the sense of light_distance():
// along the one view's axis, or for six faces along the ray from the light.
float light_distance_of(vec3 world) {
  return kLightFaces == 1 ? light_distance(shadow_coord(world).z) : length(world - u_light_pos);
}

// Light size expressed in shadow-map UV at light distance `d` (world units). For an ortho map
// the UV scale does not depend on distance; for a perspective map a world size at distance d
// covers size / (d * frustum width at distance 1) of the map.
float light_size_uv_at(float d) {
  if (u_light_ortho == 1) return u_light_size_world / light_frustum_width();
  return u_light_size_world / (max(d, 1e-4) * light_frustum_width());
}

// Unit direction from a receiver towards the light's centre.
vec3 direction_to_light(vec3 world) {
  return u_light_ortho == 1 ? -u_light_dir : normalize(u_light_pos - world);
}

// A receiver whose normal faces away from the light is in its own shadow: the ground truth
// counts every light sample behind the receiver's tangent plane as blocked (scene/light.h,
// reference/raytraced_reference.cpp), and no shadow-map bias classifies such a surface
// reliably (its depth equals the occluding front face's, up to the object's thickness).
bool faces_away_from_light(vec3 world, vec3 normal) {
  return dot(normal, direction_to_light(world)) <= 0.0;
}

// Penumbra width in shadow-map UV at the receiver, for a receiver at light distance d_r and an
// average blocker at d_b (world units, light_distance()). Fernando 2005, eq. 1 by similar
// triangles, with the light model of scene/light.h:
//  - directional (a sun of angular diameter size / D, every emitter point a parallel light):
//    w_world = (d_r - d_b) * size / D; the orthographic map's UV is world / frustum width.
//  - spot (emitter disk at the light position): w_world = size * (d_r - d_b) / d_b at the
//    receiver, where one UV unit spans d_r * (frustum width at distance 1).
float penumbra_width_uv(float d_r, float d_b) {
  float h = max(d_r - d_b, 0.0);
  if (u_light_ortho == 1) return h * u_light_size_world / (max(u_light_emitter_distance, 1e-4) * light_frustum_width());
  return u_light_size_world * h / max(d_b, 1e-4) / (max(d_r, 1e-4) * light_frustum_width());
}

// Penumbra width (shadow-map UV) of an edge `height` world units above its receiver, for a
// receiver at the middle of the light's depth range (where a spot light's UV scale is taken; a
// directional light's does not depend on depth); an edge is at most as far from the receiver as
// the light. Sizes a filter by the frame's light.
float edge_penumbra_width_uv(float height) {
  float d_r = 0.5 * (u_light_near + u_light_far);
  return penumbra_width_uv(d_r, max(d_r - height, 1e-4));
}

// Width (shadow-map UV) of the region that can hold this receiver's blockers: the penumbra of
// a blocker at the map's near plane, the farthest a blocker can be from the receiver.
float blocker_search_width_uv(float d_r) { return penumbra_width_uv(d_r, u_light_near); }
