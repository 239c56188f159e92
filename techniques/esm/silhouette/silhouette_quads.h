#pragma once
// Potential silhouette edges of a mesh as degenerate quads (Bujnak, section 4.1, Figures 3-5),
// built once per mesh on the CPU for static GPU buffers (GL-free).
//
// Each quad has four vertices, two at each end of the edge. Every vertex carries its end's
// position, the other end (for the exact distance in the fragment shader), the plane of ONE of
// the two facets, the other facet's plane, and the quad's extrusion vector (Figure 3). The
// vertex shader moves a vertex outwards when the light is in front of its plane and inwards when
// behind it (Figure 4), so a quad has area exactly when the light separates its two planes, i.e.
// when the edge is a silhouette; otherwise its four vertices collapse onto two points.
//
// Which edges get quads, and how (every choice counted in SilhouetteStats):
//  - a closed mesh (no open, non-manifold or inconsistent edge) wound inside out (negative
//    volume) is turned the right way first: its facet normals point outwards for what follows;
//  - manifold edge, the two facets coplanar: none (never a silhouette);
//  - manifold, concave (each facet in front of the other's plane): none. A concave edge's
//    silhouette never bounds the mesh's shadow: the mesh itself hides it from the light;
//  - manifold, convex, facet normals at most 90 degrees apart: one quad, extrusion vector the
//    normalised sum of the normals (it points away from the mesh, across the silhouette);
//  - manifold, convex, normals more than 90 degrees apart ("facets meet at less than 90
//    degrees", Figure 5): two quads sharing an imaginary bevel facet whose plane has the
//    normalised sum of the two normals (the in-plane outward direction for a 180-degree fold),
//    each extruded along the sum of its facet's and the bevel's normals. That keeps every
//    extrusion vector within 45 degrees of the silhouette's outward direction, so its projection
//    keeps at least 70.7% of its length (the paper's bound) and always points outwards;
//  - open (boundary) edge, one facet: the sheet ends there, so the edge is a silhouette from
//    every light not in the facet's plane: a 180-degree fold (the facet against its own flipped
//    plane) with the bevel = the in-plane direction pointing away from the facet;
//  - non-manifold (three or more facets) and inconsistently wound pairs (both facets run the
//    edge the same way): each facet's side is treated as an open edge of that facet. The quads
//    over the mesh's own interior this adds are harmless in the shadow test (a receiver whose
//    nearest texel is occluded and lies outside the edge is in shadow whatever the edge says).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "util/error.h"

namespace penumbra::esm {

// One vertex of a degenerate quad; 17 floats, the vertex buffer's layout (object space).
struct QuadVertex {
  glm::vec3 position{0.0f};     // this end of the edge
  glm::vec3 other_end{0.0f};    // the other end
  glm::vec4 plane{0.0f};        // the facet plane this vertex follows: n . x + w = 0, n unit
  glm::vec4 other_plane{0.0f};  // the quad's other plane
  glm::vec3 extrusion{0.0f};    // unit, away from the mesh across the silhouette
};
static_assert(sizeof(QuadVertex) == 17 * sizeof(float));

// Quads per mesh the static buffers hold: 1 GiB of vertices (4 x 68 bytes per quad).
inline constexpr size_t kMaxQuadsPerMesh = (size_t{1} << 30) / (4 * sizeof(QuadVertex));

struct SilhouetteOptions {
  float weld_tolerance = 1e-6f;          // x the mesh's bounding-box diagonal
  size_t max_quads = kMaxQuadsPerMesh;   // more is an Error naming the mesh
};

struct SilhouetteStats {
  size_t welded_vertices = 0, facets = 0, degenerate_triangles = 0;
  size_t edges = 0, coplanar = 0, concave = 0, convex = 0, beveled = 0;
  size_t open = 0, non_manifold = 0, inconsistent = 0;
  size_t quads = 0;
  bool flipped = false;  // a closed mesh wound inside out, turned outwards
};

struct SilhouetteGeometry {
  std::vector<QuadVertex> vertices;  // 4 per quad
  std::vector<uint32_t> indices;     // 6 per quad: (0, 1, 2), (2, 1, 3)
  SilhouetteStats stats;
  size_t quad_count() const { return vertices.size() / 4; }
};

// The quads of one mesh. Bad geometry (degenerate or zero-area triangles, open or non-manifold
// edges, no closed edge at all) is handled, never an error; more quads than options.max_quads is
// an Error naming the mesh.
Result<SilhouetteGeometry> build_silhouette_quads(const scene::Mesh& mesh, const SilhouetteOptions& options = {});

// Alpha-masked materials get no quads: their shadow edges come from the texture's alpha (the
// depth pass alpha-tests them like every shadow map), not from the geometry, whose edges are not
// where the shadow ends. Their shadows are the plain shadow map's. Blended materials cast as
// opaque in every shadow map, so they get quads.
bool casts_silhouette_quads(const scene::Scene& scene, uint32_t mesh);

// Every mesh's quads (empty for meshes that cast none); the Error names the mesh and its index.
Result<std::vector<SilhouetteGeometry>> build_scene_silhouettes(const scene::Scene& scene,
                                                                const SilhouetteOptions& options = {});

}  // namespace penumbra::esm
