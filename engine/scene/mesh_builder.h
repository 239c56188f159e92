#pragma once
// Appends simple solids to a Mesh in world units, for the built-in procedural scenes. Normals
// are smooth on curved surfaces and flat on boxes; UVs are simple per-face/per-surface ones.
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::scene::build {

// Rectangle in the XZ plane at height y, centred at `center`, normal +Y; 2 triangles.
void add_ground(Mesh& mesh, const glm::vec3& center, float size_x, float size_z);
// Box with half extents `half`, rotated by `rotation` (3x3), centred at `center`; 12 triangles.
void add_box(Mesh& mesh, const glm::vec3& center, const glm::vec3& half,
             const glm::mat3& rotation = glm::mat3(1.0f));
// The same box seen from inside (a room's walls): normals and winding turned inwards.
void add_inside_box(Mesh& mesh, const glm::vec3& center, const glm::vec3& half);
// UV sphere; 2 * slices * (stacks - 1) triangles.
void add_sphere(Mesh& mesh, const glm::vec3& center, float radius, int slices, int stacks);
// Capped cylinder from `a` to `b`; 4 * segments triangles.
void add_cylinder(Mesh& mesh, const glm::vec3& a, const glm::vec3& b, float radius, int segments);

}  // namespace penumbra::scene::build
