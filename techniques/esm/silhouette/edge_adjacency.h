#pragma once
// Edge adjacency of a triangle mesh after welding its positions (GL-free).
//
// glTF splits a vertex wherever an attribute changes (UV seams, hard normals), so two triangles
// that share an edge on the surface often share no index. Silhouette detection needs the
// surface's edges: vertices are welded by position first (within a tolerance relative to the
// mesh's size), then every edge of every non-degenerate triangle is grouped with the other
// triangles that use the same welded edge.
//
//   EdgeAdjacency adj = build_edge_adjacency(mesh, 1e-6f);
//   for (const Edge& e : adj.edges)
//     for (uint32_t k = 0; k < e.use_count; ++k) { const EdgeUse& u = adj.uses[e.first_use + k]; ... }
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::esm {

// A non-degenerate triangle in welded vertex ids, with its plane n . x + d = 0 (n unit, from
// the winding: counter-clockwise seen from the front, as glTF specifies).
struct Facet {
  uint32_t v[3] = {0, 0, 0};
  glm::vec3 normal{0.0f};
  float d = 0.0f;
};

// One facet's use of an edge: its side k runs from v[k] to v[(k + 1) % 3]; `forward` when that
// direction is the edge's a -> b.
struct EdgeUse {
  uint32_t facet = 0;
  uint8_t side = 0;
  bool forward = true;
};

// A welded edge a < b and the facets that use it: 1 = open (boundary), 2 = manifold (when the
// two run it in opposite directions; the same direction means inconsistent winding), 3 or more
// = non-manifold.
struct Edge {
  uint32_t a = 0, b = 0;
  uint32_t first_use = 0, use_count = 0;  // range in EdgeAdjacency::uses
};

struct EdgeAdjacency {
  std::vector<glm::vec3> positions;  // welded positions (object space)
  std::vector<uint32_t> weld_of;     // mesh vertex index -> welded id
  std::vector<Facet> facets;         // the mesh's non-degenerate triangles, in order
  std::vector<Edge> edges;           // sorted by (a, b)
  std::vector<EdgeUse> uses;
  size_t degenerate_triangles = 0;   // skipped: an index out of range, two corners welded together,
                                     // zero area (collinear corners) or non-finite positions

  // The corner of `facet` opposite its side `side`.
  const glm::vec3& opposite(const Facet& f, int side) const { return positions[f.v[(side + 2) % 3]]; }
};

// Welds positions closer than `relative_tolerance` x the mesh's bounding-box diagonal (and at
// least exactly equal ones), then builds the adjacency. Never fails: bad triangles are counted
// and skipped.
EdgeAdjacency build_edge_adjacency(const scene::Mesh& mesh, float relative_tolerance = 1e-6f);

}  // namespace penumbra::esm
