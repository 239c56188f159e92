#version 450 core
// This frame's silhouette quads (Bujnak, section 4.1, Figure 4's test moved before the raster):
// one thread per quad of an instance; a quad is a silhouette when the light is in front of
// exactly one of its two planes (is_silhouette in silhouette_quads.h, and the vertex shader's
// own choice of direction). Silhouettes are appended to the list and counted, six vertices
// each, into the indirect draw command, so the raster draws only them.
layout(local_size_x = SILHOUETTE_FIND_GROUP) in;
#include "silhouette_records.glsl"
layout(std430, binding = SILHOUETTE_COMMAND_BINDING) buffer SilhouetteCommand {
  uint vertex_count;  // glDrawArraysIndirect: count, instance count, first, base instance
  uint draw_instances;
  uint first_vertex;
  uint base_instance;
};
uniform vec4 u_light;          // homogeneous: (position, 1), or (-direction, 0)
uniform int u_instance_count;
uniform int u_instance_quads;  // threads with work

void main() {
  uint slot = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  if (slot >= uint(u_instance_quads)) return;
  // The instance whose slots hold this one: the last with first_slot <= slot.
  int lo = 0, hi = u_instance_count - 1;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    if (silhouette_instances[mid].first_slot <= slot) lo = mid;
    else hi = mid - 1;
  }
  uint quad = silhouette_instances[lo].first_quad + (slot - silhouette_instances[lo].first_slot);
  mat4 planes = silhouette_instances[lo].planes;
  bool front_p = dot(planes * quad_p(quad), u_light) > 0.0;
  bool front_q = dot(planes * quad_q(quad), u_light) > 0.0;
  if (front_p == front_q) return;
  uint at = atomicAdd(vertex_count, 6u) / 6u;
  silhouettes[at] = uvec2(uint(lo), quad);
}
