// The silhouette quads' storage buffers (silhouette/silhouette_buffers.h), read by the finding
// pass and by the quads' vertex shader. The bindings come as defines from SilhouetteBindings.
//
// A quad record is SilhouetteQuad: 17 floats, a (3) b (3) p (4) q (4) extrusion (3), object space.
// An instance is InstanceRecord: its world and plane matrices, the range of its mesh's quads, and
// its first thread in the finding pass (instances are listed in that order).
struct SilhouetteInstance {
  mat4 model;        // object -> world
  mat4 planes;       // inverse transpose of model: object planes -> world planes
  uint first_quad;
  uint quad_count;
  uint first_slot;
  uint unused;
};
layout(std430, binding = SILHOUETTE_QUADS_BINDING) readonly buffer SilhouetteQuads { float quad_floats[]; };
layout(std430, binding = SILHOUETTE_INSTANCES_BINDING) readonly buffer SilhouetteInstances {
  SilhouetteInstance silhouette_instances[];
};
// This frame's silhouettes: (instance, quad) pairs, written by the finding pass.
layout(std430, binding = SILHOUETTE_LIST_BINDING) buffer SilhouetteList { uvec2 silhouettes[]; };

const uint QUAD_FLOATS = 17u;
vec3 quad_vec3(uint quad, uint at) {
  uint i = quad * QUAD_FLOATS + at;
  return vec3(quad_floats[i], quad_floats[i + 1u], quad_floats[i + 2u]);
}
vec4 quad_vec4(uint quad, uint at) {
  uint i = quad * QUAD_FLOATS + at;
  return vec4(quad_floats[i], quad_floats[i + 1u], quad_floats[i + 2u], quad_floats[i + 3u]);
}
vec3 quad_a(uint quad) { return quad_vec3(quad, 0u); }
vec3 quad_b(uint quad) { return quad_vec3(quad, 3u); }
vec4 quad_p(uint quad) { return quad_vec4(quad, 6u); }
vec4 quad_q(uint quad) { return quad_vec4(quad, 10u); }
vec3 quad_extrusion(uint quad) { return quad_vec3(quad, 14u); }
