#version 450 core
// This frame's silhouette quads (Bujnak, section 4.1, Figure 4's test moved before the raster):
// one thread per quad of an instance; a quad is a silhouette when the light is in front of
// exactly one of its two planes (is_silhouette in silhouette_quads.h, and the vertex shader's
// own choice of direction). Silhouettes are appended to the list and counted, six indices
// each, into the indirect draw command, so the raster draws only them, and one work group each
// into the indirect dispatch of the compute writer (silhouette_write.comp.glsl).
layout(local_size_x = SILHOUETTE_FIND_GROUP) in;
#include "silhouette_records.glsl"
layout(std430, binding = SILHOUETTE_COMMAND_BINDING) buffer SilhouetteCommand {
  uint index_count;  // glDrawElementsIndirect: count, instance count, first index, base vertex,
  uint draw_instances;  // base instance
  uint first_index;
  uint base_vertex;
  uint base_instance;
  uint write_groups;  // glDispatchComputeIndirect: x, y, z
  uint write_groups_y;
  uint write_groups_z;
};
uniform vec4 u_light;          // homogeneous: (position, 1), or (-direction, 0)
uniform int u_instance_count;
uniform int u_instance_quads;  // threads with work

// The group's silhouettes are counted in shared memory and reserved in the list with one global
// atomic: one per silhouette made every silhouette of the frame wait on the same counter
// (FlightHelmet, 87,000 quads, on an H100: docs/results/esm.md).
shared uint group_found;
shared uint group_base;

void main() {
  if (gl_LocalInvocationIndex == 0u) group_found = 0u;
  barrier();
  uint slot = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  bool found = false;
  uint instance = 0u, quad = 0u;
  if (slot < uint(u_instance_quads)) {
    // The instance whose slots hold this one: the last with first_slot <= slot.
    int lo = 0, hi = u_instance_count - 1;
    while (lo < hi) {
      int mid = (lo + hi + 1) / 2;
      if (silhouette_instances[mid].first_slot <= slot) lo = mid;
      else hi = mid - 1;
    }
    instance = uint(lo);
    quad = silhouette_instances[lo].first_quad + (slot - silhouette_instances[lo].first_slot);
    mat4 planes = silhouette_instances[lo].planes;
    bool front_p = dot(planes * quad_p(quad), u_light) > 0.0;
    bool front_q = dot(planes * quad_q(quad), u_light) > 0.0;
    found = front_p != front_q;
  }
  uint at = found ? atomicAdd(group_found, 1u) : 0u;
  barrier();
  if (gl_LocalInvocationIndex == 0u && group_found > 0u) {
    group_base = atomicAdd(index_count, 6u * group_found) / 6u;
    atomicAdd(write_groups, group_found);
  }
  barrier();
  if (found) silhouettes[group_base + at] = uvec2(instance, quad);
}
