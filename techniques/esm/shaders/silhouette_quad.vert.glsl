#version 450 core
// Silhouette quads (Bujnak, section 4.1, Figures 3 and 4), one face (tile) of the map at a time.
// Four vertices per quad that the finding pass listed as a silhouette this frame (drawn
// indirectly, silhouette_find.comp.glsl, through a fixed index buffer: list entry i is vertices
// 4i .. 4i + 3); each builds its corner from the quad's record.
//
// Each vertex sits at one end of its edge and follows ONE of the edge's two facet planes: when
// the light is in front of that plane it moves outwards across the silhouette, when behind it
// moves inwards (Figure 4). A quad therefore has area exactly when the light separates its two
// planes, i.e. when the edge is a silhouette; otherwise its vertices collapse onto a segment and
// it rasterises nothing. The extrusion is laid out in the map's texel space, perpendicular to
// the projected edge, so every texel within the band (esm_common.glsl) gets a fragment whatever
// the projection; its length in clip space is the vertex's w times a constant (section 4.1:
// "extrusion length is evaluated from vertex w multiplied with a constant"). The edge's
// extrusion vector only says which side is outside: the bevel quads (Figure 5) keep it within
// 45 degrees of the silhouette's outward direction, so its projection is never ambiguous.
#include "esm_common.glsl"
#include "silhouette_records.glsl"
uniform mat4 u_view_proj;      // the face's world -> clip
uniform mat4 u_inv_view_proj;  // and back
uniform vec4 u_light;          // homogeneous light: (position, 1), or (-direction, 0)
uniform float u_tile_size;     // texels
flat out vec2 v_end0;          // the edge's ends in tile texels (window coordinates)
flat out vec2 v_end1;
flat out vec2 v_depth;         // their window depths
flat out vec2 v_outward;       // unit, texel space, across the edge away from the occluder
flat out vec3 v_front_depth;   // window depth of the plane facing the light: dot(xy, tile texel) + z

// Texels beyond the band the quad still covers, so that rounding in its corners never loses a
// texel centre of the band. Every extra texel is a fragment the fragment shader discards: a
// margin of half a texel made about a quarter of a short edge's fragments (FlightHelmet at 512^2).
const float QUAD_MARGIN = 0.05;

// Collapses the vertex (no area, nothing rasterised).
void collapse() {
  gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
  v_end0 = v_end1 = v_depth = v_outward = vec2(0.0);
  v_front_depth = vec3(0.0);
}

// The window depth of a world plane at a tile texel f, as dot(xy, f) + z: a plane stays a plane
// through the projection, so its NDC depth is affine in NDC x and y (and so in texels). Where the
// light's rays run along the plane there is no depth: (0, 0, -1), which no depth test accepts.
vec3 plane_window_depth(vec4 world_plane) {
  vec4 clip_plane = transpose(u_inv_view_proj) * world_plane;  // plane . (clip point) = 0
  if (abs(clip_plane.z) <= 1e-7 * length(clip_plane)) return vec3(0.0, 0.0, -1.0);
  // ndc z = -(a x + b y + d) / c with ndc x = 2 f / tile - 1; window depth = ndc z / 2 + 1 / 2.
  vec3 k = -clip_plane.xyw / clip_plane.z;
  return vec3(k.xy / u_tile_size, 0.5 * (k.z - k.x - k.y) + 0.5);
}

void main() {
  // Corner k sits at end a (k < 2) or b, and follows plane p (k even) or q.
  uvec2 listed = silhouettes[gl_VertexID / 4];
  int corner = gl_VertexID % 4;
  uint quad = listed.y;
  SilhouetteInstance instance = silhouette_instances[listed.x];
  mat4 model = instance.model;
  mat4 plane_matrix = instance.planes;
  vec3 position = corner < 2 ? quad_a(quad) : quad_b(quad);
  vec3 other_end = corner < 2 ? quad_b(quad) : quad_a(quad);
  vec4 followed_plane = (corner & 1) == 0 ? quad_p(quad) : quad_q(quad);
  vec4 other_plane = (corner & 1) == 0 ? quad_q(quad) : quad_p(quad);
  vec3 extrusion = quad_extrusion(quad);
  vec4 world0 = model * vec4(position, 1.0);
  vec4 world1 = model * vec4(other_end, 1.0);
  vec4 c0 = u_view_proj * world0, c1 = u_view_proj * world1;
  // Clip the edge to the near plane (z >= -w): the same result at both ends' vertices.
  float n0 = c0.z + c0.w, n1 = c1.z + c1.w;
  if (n0 < 0.0 && n1 < 0.0) { collapse(); return; }
  if (n0 < 0.0) c0 = mix(c0, c1, n0 / (n0 - n1));
  if (n1 < 0.0) c1 = mix(c1, c0, n1 / (n1 - n0));
  vec2 p0 = (c0.xy / c0.w * 0.5 + 0.5) * u_tile_size;
  vec2 p1 = (c1.xy / c1.w * 0.5 + 0.5) * u_tile_size;
  vec2 along = p1 - p0;
  float len = length(along);
  if (len < 1e-4) { collapse(); return; }  // seen end-on: the neighbouring edges cover it
  along /= len;
  // Outside: the side the extrusion vector points to, seen from the light. Its screen direction
  // at c0 is d(ndc) ~ e.xy c0.w - c0.xy e.w (the derivative of the perspective divide).
  vec4 e = u_view_proj * vec4(normalize(mat3(model) * extrusion), 0.0);
  vec2 toward = e.xy * c0.w - c0.xy * e.w;
  vec2 normal = vec2(-along.y, along.x);
  vec2 outward = dot(toward, normal) >= 0.0 ? normal : -normal;
  // Figure 4: in front of this vertex's plane -> outwards, behind -> inwards; QUAD_MARGIN of
  // margin beyond the band (the fragment shader cuts the band exactly). Beyond its ends the quad
  // reaches BAND_OUT further along the edge, for the outside of convex corners (see the
  // fragment shader).
  vec4 plane = plane_matrix * followed_plane;
  bool front = dot(plane, u_light) > 0.0;
  vec2 offset = front ? outward * (BAND_OUT + QUAD_MARGIN) : -outward * (BAND_IN + QUAD_MARGIN);
  offset -= along * (BAND_OUT + QUAD_MARGIN);  // this end is p0: extend away from p1
  vec4 c = c0;
  gl_Position = vec4((((p0 + offset) / u_tile_size) * 2.0 - 1.0) * c.w, c.z, c.w);
  v_end0 = p0;
  v_end1 = p1;
  v_depth = vec2(c0.z / c0.w, c1.z / c1.w) * 0.5 + 0.5;
  v_outward = outward;
  // On a silhouette exactly one plane faces the light; the occluder lies behind it (a convex
  // edge's facets and bevel are supporting planes).
  v_front_depth = plane_window_depth(front ? plane : plane_matrix * other_plane);
}
