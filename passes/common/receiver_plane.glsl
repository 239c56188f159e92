// Receiver-plane depth bias (Isidoro 2006, "Shadow mapping: GPU-based tips and techniques"), the
// one implementation every filtering technique uses (pcf, pcss, pmchss, sspcss, mpg): a
// receiver's depth is a plane in shadow-map space, so a tap at uv offset `o` is compared against
// depth + dot(o, dz_duv) instead of the centre depth, which removes acne on slanted receivers
// without a large constant bias.
// Needs: shadow_common.glsl included before. Receivers come from the frame contract's view depth
// and normal (gbuffer_read.glsl): a neighbour costs a 4-byte depth fetch.
#include "gbuffer/gbuffer_read.glsl"
#include "sampling/sampling.glsl"

// A receiver pixel in light space: shadow-map coordinate (uv, window depth) and the receiver
// plane's depth gradient d(window depth)/d(uv) (Isidoro 2006).
struct Receiver {
  vec3 coord;
  vec2 dz_duv;
  vec3 world;   // receiver_at(): its world position and unit normal, for add_receiver_plane()
  vec3 normal;
  // Six faces (add_receiver_plane): the receiver's distance and unit direction from the light,
  // and that direction's tangent basis, the frame shadow_tap() places every tap in.
  float light_dist;
  vec3 light_dir, light_t, light_b;
};

// Solves [dx.xy dy.xy] g = [dx.z dy.z] for the depth gradient g = d(window depth)/d(uv) of the
// plane through a receiver and two points beside it (all in shadow-map coordinates). Grazing
// receivers have an unbounded slope; it is capped (20 window-depth units per UV unit).
vec2 plane_depth_gradient(vec3 dx, vec3 dy) {
  float det = dx.x * dy.y - dx.y * dy.x;
  if (abs(det) < 1e-14) return vec2(0.0);  // plane seen edge-on by the light
  vec2 g = vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
  return clamp(g, vec2(-20.0), vec2(20.0));
}

// A G-buffer neighbour `step` pixels away (tried on both sides) that lies on the receiver's
// tangent plane, i.e. on the same surface: |n . (q - p)| <= 0.25 |q - p| (about 14 degrees,
// room for the smooth normal of a tessellated curved surface).
bool same_surface_neighbour(sampler2D depths, ivec2 pixel, ivec2 step, vec3 world, vec3 n, out vec3 q) {
  ivec2 size = textureSize(depths, 0);
  for (int side = 0; side < 2; ++side) {
    ivec2 t = pixel + (side == 0 ? step : -step);
    if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) continue;
    vec4 w = gbuffer_position(depths, t);
    vec3 d = w.xyz - world;
    if (w.w > 0.0 && abs(dot(d, n)) <= 0.25 * length(d) && dot(d, d) > 0.0) {
      q = w.xyz;
      return true;
    }
  }
  return false;
}

// Receiver-plane depth gradient d(window depth)/d(uv) (Isidoro 2006). Compute shaders have no
// dFdx, so we difference neighbouring G-buffer positions; a neighbour must lie on the same
// surface (checked against the normal, trying the other side when one is not) so depth edges
// and the border of the geometry do not produce a wild plane. Where no such neighbour exists (a one-pixel-wide surface) the plane
// comes from the normal alone: two points a small step along the tangent plane (1e-3 of the
// light distance; the map is linear, or locally linear for a spot light).
vec2 receiver_depth_gradient(sampler2D depths, ivec2 pixel, vec3 world, vec3 normal, vec3 c) {
  vec3 n = normalize(normal);
  vec3 qx, qy;
  if (same_surface_neighbour(depths, pixel, ivec2(1, 0), world, n, qx) &&
      same_surface_neighbour(depths, pixel, ivec2(0, 1), world, n, qy))
    return plane_depth_gradient(shadow_coord(qx) - c, shadow_coord(qy) - c);
  vec3 helper = abs(n.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 t1 = normalize(cross(n, helper));
  vec3 t2 = cross(n, t1);
  float e = 1e-3 * max(light_distance(c.z), 1e-3);  // world units
  return plane_depth_gradient(shadow_coord(world + e * t1) - c, shadow_coord(world + e * t2) - c);
}

bool inside_shadow_map(vec3 coord) { return all(greaterThanEqual(coord, vec3(0.0))) && all(lessThanEqual(coord, vec3(1.0))); }

// What a filter does at a pixel, decided from one read of its position and normal:
const int RECEIVER_LIT = 0;          // background or outside the shadow-map frustum: visibility 1
const int RECEIVER_FACES_AWAY = 1;   // normal away from the light: visibility 0 (shadow_common.glsl)
const int RECEIVER_FILTERED = 2;     // a receiver to filter
// r.coord, r.world and r.normal are set for the last two kinds (r.dz_duv by add_receiver_plane).
int receiver_at(sampler2D depths, sampler2D normals, ivec2 pixel, out Receiver r) {
  r.dz_duv = vec2(0.0);
  vec4 pos = gbuffer_position(depths, pixel);
  if (pos.w <= 0.0) return RECEIVER_LIT;
  r.world = pos.xyz;
  r.normal = gbuffer_normal(normals, pixel);
  r.coord = shadow_coord(r.world);
  if (faces_away_from_light(r.world, r.normal)) return RECEIVER_FACES_AWAY;
  return inside_shadow_map(r.coord) ? RECEIVER_FILTERED : RECEIVER_LIT;
}

// The receiver plane of a receiver (only where taps will be taken: it reads the neighbours' depths).
// Six faces need none: shadow_tap() meets the receiver's tangent plane along each tap's ray; they
// get the frame the taps are placed in instead, once per receiver rather than per tap.
void add_receiver_plane(sampler2D depths, ivec2 pixel, inout Receiver r) {
  if (kLightFaces != 1) {
    vec3 to = r.world - u_light_pos;
    r.light_dist = max(length(to), 1e-6);
    r.light_dir = to / r.light_dist;
    direction_basis(r.light_dir, r.light_t, r.light_b);
    return;
  }
  r.dz_duv = receiver_depth_gradient(depths, pixel, r.world, r.normal, r.coord);
}

// The receiver's distance from the light (world units) in the sense of light_distance(): along
// the one view's axis, or for six faces along the ray from the light, the axis of the view
// centred on the receiver that shadow_tap() places its taps in.
float receiver_light_distance(Receiver r) {
  return kLightFaces == 1 ? light_distance(r.coord.z) : length(r.world - u_light_pos);
}

// Any receiver inside the shadow-map frustum, facing the light or not, with its plane; false for
// background and outside the frustum.
bool shadow_receiver(sampler2D depths, sampler2D normals, ivec2 pixel, out Receiver r) {
  if (receiver_at(depths, normals, pixel, r) == RECEIVER_LIT || !inside_shadow_map(r.coord)) return false;
  add_receiver_plane(depths, pixel, r);
  return true;
}

// The receiver's depth extrapolated along its plane to a tap `offset_uv` away (shadow-map UV),
// minus a constant bias (window depth): what a shadow-map depth at that tap is compared with.
// The map holds one depth per texel and a tap's bilinear comparison reads texels up to one texel
// away, so a slanted receiver differs from the stored depth of its own surface by up to
// |dz/du| + |dz/dv| texels' worth ("fractional texel" error, Isidoro 2006): that is subtracted too.
float receiver_depth_at(Receiver r, vec2 offset_uv, float bias) {
  return r.coord.z + dot(offset_uv, r.dz_duv) - (abs(r.dz_duv.x) + abs(r.dz_duv.y)) * u_shadow_texel - bias;
}


// The rotation of a receiver's tap pattern (a Vogel disk), fixed to the surface: 2 pi IGN
// (Jimenez 2014) over cells of half a map texel at the receiver. The papers key IGN to the screen
// pixel (Sterna 2018, section 1), so a camera move gives every surface point a new rotation and a
// still shadow changes under a pan wherever the kernel spans several texels (docs/evaluation.md,
// "Temporal stability"); map cells stay on the surface. Cells, not a continuous coordinate: IGN
// between lattice points is a stripe pattern. A pixel's rotation is as uniformly spread as with
// the screen key, so its expected error is the same; only neighbours' correlation changes.
const float kNoiseCellsPerTexel = 2.0;
float receiver_noise_rotation(Receiver r) {
  vec2 texels;  // the receiver's position in map texels, on a lattice fixed in the world
  if (kCascades != 1 && g_cascade >= 0 && g_cascade < kCascades)
    // A cascade's square follows the camera by whole texels: the UV of a point changes by an
    // integer number of texels, in which IGN is not periodic; light-view coordinates stay.
    texels = (u_light_view * vec4(r.world, 1.0)).xy / (light_frustum_width() * u_shadow_texel);
  else
    texels = r.coord.xy / (kLightFaces == 1 ? u_shadow_texel : u_shadow_texel * u_light_face_rect[0].z);
  return noise_rotation(floor(texels * kNoiseCellsPerTexel));
}

// The rotation of a receiver's taps as the pass's rotation_noise parameter says
// (passes/sampling/rotation_noise.h): on the surface, or the papers' IGN of `screen_key` (the
// pixel, as each pass has always keyed it).
uniform int u_noise_on_screen;
float tap_rotation(Receiver r, vec2 screen_key) {
  return u_noise_on_screen == 1 ? noise_rotation(screen_key) : receiver_noise_rotation(r);
}

// The shadow-map UV offset from the receiver of a world position: shadow_coord(world) -
// r.coord for one view; for six faces, in the face-sized view centred on the receiver's direction
// that shadow_tap() places offsets in (its inverse).
vec2 shadow_offset_to(Receiver r, vec3 world) {
  if (kLightFaces == 1) return shadow_coord(world).xy - r.coord.xy;
  vec3 w = world - u_light_pos;
  return vec2(dot(w, r.light_t), dot(w, r.light_b)) / (max(dot(w, r.light_dir), 1e-6) * u_light_frustum_width);
}

// Cascades: a map UV kept inside the invocation's cascade, one texel from its tile's edges, so a
// tap's bilinear (or gathered) texels are all its own; a kernel wider than the cascade's margin
// reads its edge texels, as one map's taps do at the map's edge.
vec2 clamp_to_cascade(vec2 uv) {
  if (kCascades == 1 || g_cascade < 0 || g_cascade >= kCascades) return uv;
  vec4 rect = u_cascade_rect[g_cascade];
  return clamp(uv, rect.xy + u_shadow_texel, rect.xy + rect.z - u_shadow_texel);
}

// Where a filter tap reads the map, and what it compares there.
struct ShadowTap {
  vec2 uv;              // map UV
  float ref;            // receiver depth at the tap, bias subtracted: a texel below it is a blocker
  float distance_scale; // light_distance() of a depth read here x this = the receiver_light_distance() scale
};

// The tap `offset_uv` from the receiver, in shadow-map UV. One view: r.coord.xy + offset_uv,
// against the receiver plane (receiver_depth_at). Six faces: offsets are UV of a face-sized view
// centred on the receiver's direction w0 from the light, so the tap is the direction
// w = normalize(w0 + (offset.x t + offset.y b) u_light_frustum_width) (t, b: w0's basis), read in
// the face w belongs to: a kernel that crosses a face edge goes on in the next face, no seam. It is
// compared with the depth, in that face, of the point where the ray along w meets the receiver's
// tangent plane (the receiver-plane bias of Isidoro 2006 in exact form), less the plane's depth
// change over one texel (his fractional-texel term) and `bias`.
const float kMaxFractionalTexel = 0.05;
ShadowTap shadow_tap(Receiver r, vec2 offset_uv, float bias) {
  ShadowTap t;
  if (kLightFaces == 1) {
    t.uv = clamp_to_cascade(r.coord.xy + offset_uv);
    t.ref = receiver_depth_at(r, offset_uv, bias);
    t.distance_scale = 1.0;
    return t;
  }
  float d = r.light_dist;
  vec3 w = normalize(r.light_dir + (r.light_t * offset_uv.x + r.light_b * offset_uv.y) * u_light_frustum_width);
  float nw = dot(r.normal, w);  // negative: the receiver faces the light
  // The plane's distance along w, within [d / 2, 2 d]: a grazing receiver's plane passes near the
  // light, and unbounded it would lift taps over casters between (like the one-view gradient cap).
  float along = nw < -1e-3 ? clamp(dot(r.normal, r.world - u_light_pos) / nw, 0.5 * d, 2.0 * d) : d;
  // At grazing incidence the plane's change over a texel grows without bound; past 5 % of the
  // distance it would lift the receiver over casters near it (a light inside a shell).
  float tan_incidence = sqrt(max(1.0 - nw * nw, 0.0)) / max(-nw, 1e-3);
  along -= along * min(tan_incidence * u_shadow_texel * u_light_frustum_width, kMaxFractionalTexel);
  int face = light_face(w);
  vec3 c = face_shadow_coord(face, u_light_pos + w * along);
  t.uv = c.xy;
  t.ref = c.z - bias;
  t.distance_scale = axis_to_ray_scale_of(w);
  return t;
}
