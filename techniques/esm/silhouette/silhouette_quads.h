#pragma once
// Potential silhouette edges of a mesh as degenerate quads (Bujnak, section 4.1, Figures 3-5),
// built once per mesh on the CPU for static GPU buffers (GL-free).
//
// Each quad has four vertices, two at each end of the edge. Every vertex carries its end's
// position, the other end (for the exact distance in the fragment shader), the plane of ONE of
// the two facets, the other facet's plane, and the quad's extrusion vector (Figure 3). The
// vertex shader moves a vertex outwards when the light is in front of its plane and inwards when
// behind it (Figure 4), so a quad has area exactly when the light separates its two planes, i.e.
// when the edge is a silhouette. The paper draws every quad and lets the others collapse; here a
// compute pass first keeps the quads that are silhouettes this frame (is_silhouette), so the
// raster work grows with the silhouettes, not with the mesh (silhouette_buffers.h). One record
// per quad holds what its four vertices need (SilhouetteQuad).
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

// One degenerate quad (object space), 17 floats, the layout of the storage buffer the GPU finds
// silhouettes in and draws from (shaders/silhouette_records.glsl). Its four vertices are made in
// the vertex shader: vertex k sits at `a` (k = 0, 1) or `b` (k = 2, 3) and follows plane `p`
// (k even) or `q` (k odd); each vertex also knows the other end and the other plane.
struct SilhouetteQuad {
  glm::vec3 a{0.0f}, b{0.0f};  // the edge's ends
  glm::vec4 p{0.0f}, q{0.0f};  // the two planes: n . x + w = 0, n unit
  glm::vec3 extrusion{0.0f};   // unit, away from the mesh across the silhouette
};
static_assert(sizeof(SilhouetteQuad) == 17 * sizeof(float));

// The quad is a silhouette from `light` (homogeneous: (position, 1), or (-direction, 0)) when the
// light is in front of exactly one of its planes; what the finding pass and the vertex shader test.
inline bool is_silhouette(const SilhouetteQuad& quad, const glm::vec4& light) {
  return (glm::dot(quad.p, light) > 0.0f) != (glm::dot(quad.q, light) > 0.0f);
}

// The boundary of a sheet (a facet of unit normal `normal`) along a-b, `away` the direction in its
// plane pointing away from it: the edge is a silhouette from every light not in that plane, a
// 180-degree fold of the facet against its own flipped plane, bevelled along `away` (two quads
// appended to `quads`). Open mesh edges and alpha-mask contours (alpha_contours.h) are such edges.
void add_sheet_boundary(std::vector<SilhouetteQuad>& quads, const glm::vec3& a, const glm::vec3& b,
                        const glm::vec3& normal, const glm::vec3& away);

// Edges a mesh may have: 2^24 (16,777,216). More is an Error naming the mesh and this limit.
// Every edge gives at most two quads (a bevel) per facet using it, so the per-mesh buffers stay
// within a few GiB at worst; the scene's total must also fit the GL's largest storage buffer.
inline constexpr size_t kMaxEdgesPerMesh = size_t{1} << 24;

// Texel cells of an alpha-masked mesh's texture footprints traced at load (alpha_contours.h):
// 2^27, about 2.4 s at worst in a release build (a 4096^2 footprint of a dense mask takes 0.6 s).
// The triangles beyond are skipped and counted (a mask tiled many times over a large mesh), their
// shadows the plain map's.
inline constexpr size_t kMaxContourCellsPerMesh = size_t{1} << 27;

struct SilhouetteOptions {
  float weld_tolerance = 1e-6f;          // x the mesh's bounding-box diagonal
  size_t max_edges = kMaxEdgesPerMesh;   // more is an Error naming the mesh
  bool alpha_contours = true;            // alpha-masked meshes: their mask's contour, or no quads
  size_t max_contour_cells = kMaxContourCellsPerMesh;  // per mesh; triangles beyond are skipped
};

struct SilhouetteStats {
  size_t welded_vertices = 0, facets = 0, degenerate_triangles = 0;
  size_t edges = 0, coplanar = 0, concave = 0, convex = 0, beveled = 0;
  size_t open = 0, non_manifold = 0, inconsistent = 0;
  size_t quads = 0;
  size_t alpha_contours = 0;  // alpha-mask contour pieces (alpha_contours.h), one boundary each
  size_t alpha_skipped = 0;   // masked triangles whose texture footprint was too large to trace
  bool flipped = false;  // a closed mesh wound inside out, turned outwards
};

struct SilhouetteGeometry {
  std::vector<SilhouetteQuad> quads;
  SilhouetteStats stats;
  size_t quad_count() const { return quads.size(); }
};

// The quads of one mesh. Bad geometry (degenerate or zero-area triangles, open or non-manifold
// edges, no closed edge at all) is handled, never an error; more welded edges than
// options.max_edges is an Error naming the mesh and the limit, found before any quad is made.
Result<SilhouetteGeometry> build_silhouette_quads(const scene::Mesh& mesh, const SilhouetteOptions& options = {});

// Every mesh's quads; the Error names the mesh and its index. Alpha-masked meshes get the quads
// of their mask's contour instead of their edges (alpha_contours.h): their shadow ends where the
// texture's alpha crosses the cutoff (the depth pass alpha-tests them like every shadow map), not
// at the geometry's edges; with options.alpha_contours false they get none, and their shadows
// are the plain map's. Blended materials cast as opaque in every shadow map: edge quads.
Result<std::vector<SilhouetteGeometry>> build_scene_silhouettes(const scene::Scene& scene,
                                                                const SilhouetteOptions& options = {});

}  // namespace penumbra::esm
