#pragma once
// Silhouettes of alpha-masked casters (glTF MASK: leaves, fences, decals) for the extended map
// (GL-free). The shadow of such a caster ends where its texture's alpha crosses the material's
// cutoff, not at the mesh's edges, so its quads come from the alpha mask: the contour of the
// mask is traced in texture space, triangle by triangle, and every piece of it is a boundary of
// the opaque sheet (add_sheet_boundary: a silhouette from every light not in the facet's plane).
// The paper leaves alpha-keyed shadows as an extension (Bujnak, section 6).
//
// The documented approximation:
//  - the mask is the nearest texel's alpha of mip level 0 with repeat wrap, times the base
//    colour factor's alpha, against the cutoff: what the ray-traced reference tests;
//  - its outline is a staircase of texel sides; the contour joins the midpoints of the
//    staircase's steps (marching squares on the texel centres), so a diagonal staircase becomes
//    its straight mean line, and the points are thinned to within kContourTolerance texels
//    (Douglas-Peucker). Diagonal neighbours do not connect;
//  - the mesh's own edges where the mask is opaque up to them get no quads (the plain depth
//    test decides there), nor do the mask's contours on triangles whose texture footprint
//    exceeds kMaxContourCells texel cells, or once the mesh's triangles have traced
//    SilhouetteOptions::max_contour_cells (counted in SilhouetteStats::alpha_skipped).
//
//   Result<SilhouetteGeometry> g = build_alpha_contour_quads(mesh, material, &image);
#include <cstddef>

#include "scene/scene.h"
#include "techniques/esm/silhouette/silhouette_quads.h"
#include "util/error.h"

namespace penumbra::esm {

// Douglas-Peucker tolerance of the traced contour, texture texels.
inline constexpr float kContourTolerance = 0.75f;
// Texel cells a triangle's texture footprint may span before its contour is skipped: a 4096^2
// texture and its border fit (the trace keeps a byte a cell, 32 MiB at most).
inline constexpr size_t kMaxContourCells = size_t{1} << 25;

// The quads of a masked mesh: its contour pieces inside each triangle, mapped to object space.
// `image` may be null (no texture): the factor's alpha alone decides, and a covered mesh gets
// build_silhouette_quads' quads, an uncovered one none. More contour pieces than
// options.max_edges is an Error naming the mesh.
Result<SilhouetteGeometry> build_alpha_contour_quads(const scene::Mesh& mesh, const scene::Material& material,
                                                     const scene::Image* image, const SilhouetteOptions& options = {});

}  // namespace penumbra::esm
