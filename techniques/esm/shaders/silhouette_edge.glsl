// One silhouette edge in a face (tile) of the extended map (Bujnak, section 4.1, Figures 3 and 4),
// shared by the two ways the quads reach the map: the raster (silhouette_quad.vert.glsl builds the
// quad's corners from project_silhouette, silhouette_quad.frag.glsl runs silhouette_texel per
// fragment) and the compute writer (silhouette_write.comp.glsl runs both per texel), so that the
// two write the same map. Needs esm_common.glsl, esm_views.glsl and silhouette_records.glsl.
uniform mat4 u_view_proj;         // the face's world -> clip
uniform mat4 u_inv_view_proj;     // and back
uniform vec4 u_light;             // homogeneous light: (position, 1), or (-direction, 0)
uniform float u_tile_size;        // texels
uniform vec2 u_tile_origin;       // texels
uniform sampler2D u_depth;        // the depth pass's (biased) depth, whole map
uniform float u_hidden_tolerance; // texel footprints (world size of a texel at the edge's distance)
uniform int u_face;               // the face (tile) being written

// What a texel test needs of the edge (the raster passes it as flat varyings).
struct QuadEdge {
  vec2 end0, end1;   // the edge's ends a and b in tile texels (window coordinates)
  vec2 depth;        // their window depths
  vec2 outward;      // unit, texel space, across the edge away from the occluder
  vec3 front_depth;  // window depth of the plane facing the light: dot(xy, tile texel) + z
};

// The edge projected into the face, and which of its two planes face the light.
struct ProjectedSilhouette {
  QuadEdge edge;
  vec4 clip0, clip1;     // the ends in clip space, clipped to the near plane
  bool p_front, q_front;
};

// Texels beyond the band the quad still covers, so that rounding in its corners never loses a
// texel centre of the band. Every extra texel is a fragment (or a compute test) that the texel
// test rejects: a margin of half a texel made about a quarter of a short edge's fragments
// (FlightHelmet at 512^2).
const float QUAD_MARGIN = 0.05;

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

// Quad `quad` of instance `instance` in this face. False where it has nothing to write: wholly
// behind the near plane, or seen end-on (the neighbouring edges cover it).
bool project_silhouette(uint instance_index, uint quad, out ProjectedSilhouette s) {
  SilhouetteInstance instance = silhouette_instances[instance_index];
  mat4 model = instance.model;
  vec4 world0 = model * vec4(quad_a(quad), 1.0);
  vec4 world1 = model * vec4(quad_b(quad), 1.0);
  vec4 c0 = u_view_proj * world0, c1 = u_view_proj * world1;
  // Clip the edge to the near plane (z >= -w).
  float n0 = c0.z + c0.w, n1 = c1.z + c1.w;
  if (n0 < 0.0 && n1 < 0.0) return false;
  if (n0 < 0.0) c0 = mix(c0, c1, n0 / (n0 - n1));
  if (n1 < 0.0) c1 = mix(c1, c0, n1 / (n1 - n0));
  vec2 p0 = (c0.xy / c0.w * 0.5 + 0.5) * u_tile_size;
  vec2 p1 = (c1.xy / c1.w * 0.5 + 0.5) * u_tile_size;
  vec2 along = p1 - p0;
  if (length(along) < 1e-4) return false;
  along = normalize(along);
  // Outside: the side the extrusion vector points to, seen from the light. Its screen direction
  // at c0 is d(ndc) ~ e.xy c0.w - c0.xy e.w (the derivative of the perspective divide). The
  // bevel quads (Figure 5) keep the extrusion within 45 degrees of the silhouette's outward
  // direction, so its projection is never ambiguous.
  vec4 e = u_view_proj * vec4(normalize(mat3(model) * quad_extrusion(quad)), 0.0);
  vec2 toward = e.xy * c0.w - c0.xy * e.w;
  vec2 normal = vec2(-along.y, along.x);
  vec4 p = instance.planes * quad_p(quad), q = instance.planes * quad_q(quad);
  s.p_front = dot(p, u_light) > 0.0;
  s.q_front = dot(q, u_light) > 0.0;
  s.clip0 = c0;
  s.clip1 = c1;
  s.edge.end0 = p0;
  s.edge.end1 = p1;
  s.edge.depth = vec2(c0.z / c0.w, c1.z / c1.w) * 0.5 + 0.5;
  s.edge.outward = dot(toward, normal) >= 0.0 ? normal : -normal;
  // On a silhouette exactly one plane faces the light; the occluder lies behind it (a convex
  // edge's facets and bevel are supporting planes).
  s.edge.front_depth = plane_window_depth(s.p_front ? p : q);
  return true;
}

// The texel's surface (depth attachment) is nearer the light than window depth `depth` by more
// than the tolerance.
bool nearer_surface(ivec2 map_texel, float depth) {
  float occluder = texelFetch(u_depth, map_texel, 0).r;
  float distance = esm_light_distance(depth);
  return esm_light_distance(occluder) < distance - u_hidden_tolerance * esm_texel_world(u_face, distance);
}

// One texel of a silhouette quad, at tile coordinates f (its centre) and whole-map texel
// `map_texel`: its exact signed distance from the projected edge's line (texels) and the line's
// outward direction, the edge's depth there, and the encoding of esm_common.glsl (edge,
// edge_depth, edge_near) in `value`; false for texels it does not write. Nothing beyond the band.
// Beyond the edge's ends only the outer side is written, with the distance to the nearer end (and
// the direction from it), up to BAND_OUT: the outside of a convex corner of the silhouette (which
// no quad's band reaches) then gets its exact distance, the corner's, while the inside of the
// shape near a reflex corner, which such a cap would call outside, keeps the adjacent edge's
// inside value (MAX keeps an inside over an outside) or is left to the plain depth test.
// Silhouettes of small triangles (a tessellated sphere seen from a grazing
// light) zigzag in sub-texel steps: without the caps, the outer band would be full of holes.
//
// Hidden edges write nothing (section 3.1: "hidden silhouette edges should not be rendered"):
// outside the occluder, where the texel's surface is nearer the light than the edge; inside it,
// where the texel's surface is nearer than the plane of the facet facing the light. The
// occluder lies behind that plane, so its own surface is never nearer: what is, is another
// object in front (a beam over the top of a pole hanging from it). Both by more than
// u_hidden_tolerance texel footprints (the depth attachment carries the polygon offset).
bool silhouette_texel(QuadEdge q, vec2 f, ivec2 map_texel, out vec3 value) {
  value = vec3(0.0);
  vec2 edge = q.end1 - q.end0;
  float len = length(edge);
  float s = dot(f - q.end0, edge) / (len * len);
  float d = dot(f - q.end0, q.outward);  // texels, > 0 outside the occluder
  if (d > BAND_OUT || d < -BAND_IN) return false;
  float beyond = max(-s, s - 1.0) * len;  // texels past the nearer end, <= 0 along the edge
  vec2 outward = q.outward;
  if (beyond > 1e-3) {
    if (d < 0.0) return false;
    vec2 from_end = f - (s < 0.0 ? q.end0 : q.end1);
    d = length(from_end);
    if (d > BAND_OUT) return false;
    outward = from_end / d;  // the cap's tangent line at the texel
  }
  float edge_depth = mix(q.depth.x, q.depth.y, clamp(s, 0.0, 1.0));  // affine along a projected line
  if (d >= 0.0) {
    if (nearer_surface(map_texel, edge_depth)) return false;
  } else {
    float own = dot(q.front_depth.xy, f) + q.front_depth.z;
    if (own >= 0.0 && own <= 1.0 && nearer_surface(map_texel, own)) return false;
  }
  value = esm_encode_quad(d, outward, edge_depth);
  return true;
}
