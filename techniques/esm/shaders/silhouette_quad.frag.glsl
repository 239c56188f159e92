#version 450 core
// One texel of a silhouette quad (silhouette_texel in silhouette_edge.glsl), into the map's three
// channels (esm_common.glsl).
#include "esm_common.glsl"
#include "esm_views.glsl"
#include "silhouette_records.glsl"
#include "silhouette_edge.glsl"
flat in vec2 v_end0;
flat in vec2 v_end1;
flat in vec2 v_depth;
flat in vec2 v_outward;
flat in vec3 v_front_depth;
layout(location = 0) out float o_edge;
layout(location = 1) out float o_edge_depth;
// The nearest edge by an image atomic, not a third blended target: on the GPUs we measure a third
// MAX-blended R32F attachment doubled the pass (docs/results/esm.md).
layout(r32ui, binding = 2) uniform uimage2D u_edge_near_bits;

void main() {
  vec3 value;
  QuadEdge q = QuadEdge(v_end0, v_end1, v_depth, v_outward, v_front_depth);
  if (!silhouette_texel(q, gl_FragCoord.xy - u_tile_origin, ivec2(gl_FragCoord.xy), value)) discard;
  o_edge = value.x;
  o_edge_depth = value.y;
  imageAtomicMax(u_edge_near_bits, ivec2(gl_FragCoord.xy), floatBitsToUint(value.z));
}
