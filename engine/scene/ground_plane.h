#pragma once
// A receiver for models that bring none: many glTF models (a helmet, an animal, a truck) float in
// empty space, so their shadows fall on nothing. has_ground tells whether a model already has a
// floor; add_ground_plane puts one under it, wide enough to catch its shadows.
//
//   if (!has_ground(scene)) add_ground_plane(scene);   // scene.bounds now include the plane
#include <string_view>

#include "scene/scene.h"

namespace penumbra::scene {

// Name of the mesh and material add_ground_plane adds.
inline constexpr std::string_view kGroundPlaneName = "penumbra_ground";

// True when upward-facing triangles (face normal within about 25 degrees of +Y, on the side the
// vertex normals point to) lying at the bottom of the bounds cover at least kGroundCoverage of
// the bounds' footprint (x-z area) and reach its edges on every side: a floor the whole model
// stands on, not the underside of a box, a stand's small base, or a board with pieces lying
// beside it on nothing.
inline constexpr double kGroundCoverage = 0.6;
bool has_ground(const Scene& scene);

// Adds a square, upward-facing plane just below the lowest point of the scene, centred under it:
// half-width = the larger horizontal half-extent + the height (a shadow from a light 45 degrees
// up reaches that far). Instances, bounds and a grey material follow; returns the mesh index.
size_t add_ground_plane(Scene& scene);

// True when `scene` holds a plane add_ground_plane added.
bool has_added_ground_plane(const Scene& scene);

}  // namespace penumbra::scene
