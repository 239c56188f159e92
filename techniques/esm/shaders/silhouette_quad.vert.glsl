#version 450 core
// Silhouette quads (Bujnak, section 4.1, Figures 3 and 4), one face (tile) of the map at a time.
// Four vertices per listed quad (drawn indirectly, silhouette_find.comp.glsl, through a fixed
// index buffer: list entry i is vertices 4i .. 4i + 3); each builds its corner from the quad's
// record (silhouette_edge.glsl).
//
// Each vertex sits at one end of its edge and follows ONE of the edge's two facet planes: when
// the light is in front of that plane it moves outwards across the silhouette, when behind it
// moves inwards (Figure 4). A quad therefore has area exactly when the light separates its two
// planes, i.e. when the edge is a silhouette; otherwise its vertices collapse onto a segment and
// it rasterises nothing. The extrusion is laid out in the map's texel space, perpendicular to
// the projected edge, so every texel within the band (esm_common.glsl) gets a fragment whatever
// the projection; its length in clip space is the vertex's w times a constant (section 4.1:
// "extrusion length is evaluated from vertex w multiplied with a constant").
#include "esm_common.glsl"
#include "esm_views.glsl"
#include "silhouette_records.glsl"
#include "silhouette_edge.glsl"
flat out vec2 v_end0;          // QuadEdge, field by field (silhouette_edge.glsl)
flat out vec2 v_end1;
flat out vec2 v_depth;
flat out vec2 v_outward;
flat out vec3 v_front_depth;

// Collapses the vertex (no area, nothing rasterised).
void collapse() {
  gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
  v_end0 = v_end1 = v_depth = v_outward = vec2(0.0);
  v_front_depth = vec3(0.0);
}

void main() {
  // Corner k sits at end a (k < 2) or b, and follows plane p (k even) or q.
  uvec2 listed = silhouettes[gl_VertexID / 4];
  int corner = gl_VertexID % 4;
  ProjectedSilhouette s;
  if (!project_silhouette(listed.x, listed.y, s)) { collapse(); return; }
  bool at_a = corner < 2;
  vec2 end = at_a ? s.edge.end0 : s.edge.end1;
  vec4 c = at_a ? s.clip0 : s.clip1;
  vec2 along = normalize(s.edge.end1 - s.edge.end0);
  // Figure 4: in front of this vertex's plane -> outwards, behind -> inwards; QUAD_MARGIN of
  // margin beyond the band (the texel test cuts the band exactly). Beyond its ends the quad
  // reaches BAND_OUT further along the edge, for the outside of convex corners
  // (silhouette_texel).
  bool front = (corner & 1) == 0 ? s.p_front : s.q_front;
  vec2 offset = front ? s.edge.outward * (BAND_OUT + QUAD_MARGIN) : -s.edge.outward * (BAND_IN + QUAD_MARGIN);
  offset += (at_a ? -along : along) * (BAND_OUT + QUAD_MARGIN);  // away from the other end
  gl_Position = vec4((((end + offset) / u_tile_size) * 2.0 - 1.0) * c.w, c.z, c.w);
  v_end0 = s.edge.end0;
  v_end1 = s.edge.end1;
  v_depth = s.edge.depth;
  v_outward = s.edge.outward;
  v_front_depth = s.edge.front_depth;
}
