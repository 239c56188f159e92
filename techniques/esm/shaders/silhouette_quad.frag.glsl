#version 450 core
// One texel of a silhouette quad: its exact signed distance from the projected edge's line
// (texels), the edge's depth there, and the encoding of esm_common.glsl; nothing beyond the band.
// Beyond the edge's ends only the outer side is written, with the distance to the nearer end, up
// to BAND_OUT: the outside of a convex corner of the silhouette (which no quad's band reaches)
// then gets its exact distance, the corner's, while the inside of the shape near a reflex
// corner, which such a cap would call outside, keeps the adjacent edge's inside value (MAX keeps
// the most shadowed) or is left to the plain depth test. Silhouettes of small
// triangles (a tessellated sphere seen from a grazing light) zigzag in sub-texel steps: without
// this, the outer band would be full of holes.
//
// Hidden edges write nothing (section 3.1: "hidden silhouette edges should not be rendered"):
// outside the occluder, where the texel's surface is nearer the light than the edge; inside it,
// where the texel's surface is nearer than the plane of the facet facing the light. The
// occluder lies behind that plane, so its own surface is never nearer: what is, is another
// object in front (a beam over the top of a pole hanging from it). Both by more than
// u_hidden_tolerance texel footprints (the depth attachment carries the polygon offset).
#include "esm_common.glsl"
#include "esm_views.glsl"
flat in vec2 v_end0;
flat in vec2 v_end1;
flat in vec2 v_depth;
flat in vec2 v_outward;
flat in vec3 v_front_depth;  // the front plane's window depth: dot(xy, tile texel) + z (-1: none)
uniform vec2 u_tile_origin;       // texels
uniform sampler2D u_depth;        // the depth pass's (biased) depth, whole map
uniform float u_hidden_tolerance; // texel footprints (world size of a texel at the edge's distance)
uniform int u_face;               // the face (tile) being drawn

// The texel's surface (depth attachment) is nearer the light than window depth `depth` by more
// than the tolerance.
bool nearer_surface(float depth) {
  float occluder = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
  float distance = esm_light_distance(depth);
  return esm_light_distance(occluder) < distance - u_hidden_tolerance * esm_texel_world(u_face, distance);
}
layout(location = 0) out vec2 o_esm;

void main() {
  vec2 f = gl_FragCoord.xy - u_tile_origin;  // texel centre, tile coordinates
  vec2 edge = v_end1 - v_end0;
  float len = length(edge);
  float s = dot(f - v_end0, edge) / (len * len);
  float d = dot(f - v_end0, v_outward);  // texels, > 0 outside the occluder
  if (d > BAND_OUT || d < -BAND_IN) discard;
  float beyond = max(-s, s - 1.0) * len;  // texels past the nearer end, <= 0 along the edge
  if (beyond > 1e-3) {
    if (d < 0.0) discard;
    d = length(f - (s < 0.0 ? v_end0 : v_end1));
    if (d > BAND_OUT) discard;
  }
  float edge_depth = mix(v_depth.x, v_depth.y, clamp(s, 0.0, 1.0));  // affine along a projected line
  if (d >= 0.0) {
    if (nearer_surface(edge_depth)) discard;
  } else {
    float own = dot(v_front_depth.xy, f) + v_front_depth.z;
    if (own >= 0.0 && own <= 1.0 && nearer_surface(own)) discard;
  }
  o_esm = esm_encode_quad(1.0 - edge_transfer(quad_coordinate(d)), edge_depth);
}
