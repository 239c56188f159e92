#pragma once
// Shadow debug geometry (as Unity's and Unreal's shadow views offer), GL-free and unit-tested:
// the light's shadow frustum and its emitter outline as world-space segments, clipped and
// projected onto the frame; and the blocker-search region of a receiver point: every blocker
// that can shadow it lies in the cone from the point to the emitter disk, so the region is the
// convex hull of that cone projected into the shadow map.
//
//   auto lines = project_segments(frustum_segments(f), camera, w, h);   // frame pixels
//   auto region = blocker_search_region(receiver, light, f);          // shadow-map uv polygon
#include <optional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/light.h"

namespace penumbra::sandbox {

using Segment = std::pair<glm::vec3, glm::vec3>;

// The 12 edges of the frustum (the corners of the NDC cube through inverse(view_proj)).
std::vector<Segment> frustum_segments(const scene::ShadowFrustum& frustum);
// The emitter: its disk's outline in `segments` pieces plus a short arrow along the light's
// direction from its centre (point lights: the disk facing `direction`).
std::vector<Segment> emitter_segments(const scene::Light& light, int segments = 32);

// Segments clipped to the camera's near side and projected to frame pixels (origin top-left).
std::vector<std::pair<glm::vec2, glm::vec2>> project_segments(const std::vector<Segment>& segments,
                                                              const scene::Camera& camera, int width, int height);

// The convex hull (counter-clockwise) of the shadow-map uv of `receiver` and of `samples` points
// on the emitter outline; empty when the receiver is outside the frustum.
std::vector<glm::vec2> blocker_search_region(const glm::vec3& receiver, const scene::Light& light,
                                             const scene::ShadowFrustum& frustum, int samples = 24);

// Points of the emitter outline (world), `count` of them.
std::vector<glm::vec3> emitter_outline(const scene::Light& light, int count);

// Distance from the emitter plane (directional) or light position (spot) of shadow-map window
// depth `depth` in [0, 1] (the frustum's near/far, linearised for perspective maps).
float light_distance(const scene::ShadowFrustum& frustum, float depth);
// Shadow-map window depth of world point `p`.
float shadow_depth(const scene::ShadowFrustum& frustum, const glm::vec3& p);
// The penumbra a blocker at `blocker_distance` from a light `light_size` across casts on a
// receiver at `receiver_distance` (similar triangles, Fernando's PCSS estimate), world units.
float penumbra_width(float light_size, float receiver_distance, float blocker_distance);

}  // namespace penumbra::sandbox
