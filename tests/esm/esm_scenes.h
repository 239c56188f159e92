#pragma once
// Scenes the esm tests build themselves (no files): a room lit by a point light inside it,
// the paper's two crossed pipes in front of a wall (Figures 9-11), plates lying on the ground and
// a tilted sheet, and helpers.
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::test {

// Thin plates (`thickness` high) lying on a ground plane at several angles, and an open sheet
// floating above them, rising towards +x, lit by a zero-size spot light at `light` (on the +x
// side, aimed at the plates). Each plate casts a shadow a few texels wide along its own contact
// line (a window frame on its pane), the thinner in texels the higher the light. Lit from well
// above the sheet, the sheet is lit all over, and its rim on the light's side is both its own
// silhouette edge and its nearest point to the light.
scene::Scene plates_and_sheet(float thickness, const glm::vec3& light);

// A closed 8 m room (walls facing inwards, |x|, |y|, |z| <= 4) lit by a zero-size point light at
// `light`, with rods and a ball around the light whose shadows cross the point light's face
// boundaries on the walls. The camera is at the light.
scene::Scene point_lit_room(const glm::vec3& light);

// Two pipes (capped cylinders, radius `radius`) crossing at right angles in front of a wall at
// z = 0, `gap` apart in depth (0: they intersect), lit by a zero-size spot light from the front.
scene::Scene crossed_pipes(float radius, float gap);

// The camera looking from `eye` at `target` (vertical field of view in degrees).
scene::Camera view(const glm::vec3& eye, const glm::vec3& target, float fov_deg);

}  // namespace penumbra::test
