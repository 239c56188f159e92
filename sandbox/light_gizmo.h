#pragma once
// The light gizmo: the sky over the scene as a disk in the viewport's corner, the zenith at its
// centre and the horizon at its rim (equidistant: the distance from the centre is the angle
// from the zenith), turned so that up on the disk is where the camera looks. The light is a dot
// where it shines from; dragging the dot sets the light's direction. GL-free, unit-tested.
//
//   glm::vec2 p = gizmo_point(light.direction, camera);         // disk coordinates, |p| <= 1
//   light.direction = gizmo_direction(p_under_mouse, camera);   // unit, light -> scene
#include <glm/glm.hpp>

#include "scene/camera.h"

namespace penumbra::sandbox {

inline constexpr float kGizmoRadius = 56.0f;  // pixels

// Where a light shining along `direction` sits on the disk: x right, y up (towards the camera's
// view direction); the rim is the horizon. Lights from below the horizon sit on the rim.
glm::vec2 gizmo_point(const glm::vec3& direction, const scene::Camera& camera);
// The light direction (unit, light -> scene) for disk point `p`; points outside the disk are
// taken to its rim.
glm::vec3 gizmo_direction(glm::vec2 p, const scene::Camera& camera);

}  // namespace penumbra::sandbox
