#pragma once
// Framing a model so its shadows show: a camera fitted to the model's bounds, clip planes that
// let the camera come close and back away, and a light chosen so shadows fall where the camera
// sees them. Pure geometry (no GL, no files); staging.h applies it to a loaded Scene.
//
//   Camera cam = fit_camera(model_bounds, 16.0f / 9.0f);
//   fit_clip_planes(cam, scene.bounds);
//   Light sun = default_light(scene.bounds, cam.forward());
#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::scene {

// Front-above three-quarter view (from +X, +Y, +Z towards the model): most glTF models face +Z
// or +X, so both the front and one side are seen.
inline const glm::vec3 kDefaultViewDirection{-0.5f, -0.42f, -0.76f};

// A camera looking along `view_direction` at the centre of `bounds`, at the distance where the
// bounds' eight corners just fit the vertical field of view and `aspect` (width / height) with
// a margin of `margin` (fraction of the frame on each side). Clip planes from fit_clip_planes.
Camera fit_camera(const Bounds& bounds, float aspect, const glm::vec3& view_direction = kDefaultViewDirection,
                  float fov_y = glm::radians(50.0f), float margin = 0.06f);

// near/far for `camera` and a scene of `bounds`: far reaches well past the far side (the camera
// may back away a few radii), near is a small fraction of the scene's radius so the camera can
// come close to a surface without clipping it (DEPTH32F keeps the ratio harmless).
void fit_clip_planes(Camera& camera, const Bounds& bounds);

// The light of a scene with none of its own: directional, from above and behind the model as
// seen along `view_direction` (turned 60 degrees to the side), so shadows fall towards the
// camera and across the receiver, beside the model rather than hidden behind or under it.
// The emitter's angular diameter is kDefaultLightAngle (a soft sun).
inline constexpr float kDefaultLightAngle = 0.04f;  // radians (about 2.3 degrees)
glm::vec3 default_light_direction(const glm::vec3& view_direction);
Light default_light(const Bounds& bounds, const glm::vec3& view_direction);

// The file's own light (KHR_lights_punctual): the first directional light, else the first
// spot, else the first point light; nullopt without any. Punctual lights have no size, so the
// emitter gets an angular diameter of kDefaultLightAngle as seen from the scene centre (a
// directional light's emitter disk is placed like default_light's).
std::optional<Light> file_light(const Scene& scene);

// Turns `light` to `direction` (normalised; a zero vector changes nothing). A directional
// light's emitter disk keeps its distance from the centre of `bounds` (at least two radii),
// now along -direction; spot and point lights keep their position.
void set_light_direction(Light& light, glm::vec3 direction, const Bounds& bounds);

// A camera placed by a glTF node: perspective, looking down the node's -Z with +Y up (roll is
// not kept: Camera has yaw and pitch only).
Camera camera_from_node(const glm::mat4& world, float yfov, float znear, float zfar);

}  // namespace penumbra::scene
