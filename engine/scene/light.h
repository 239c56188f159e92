#pragma once
// Area lights with a physical size, shared by every technique and both references so they agree
// on what "soft" means.
//
// THE definition of size: `Light::size` is the DIAMETER (world units) of a flat emitter disk
// centred at `position`, lying in the plane perpendicular to `direction`. Same for both types:
//  - directional: the disk sits at `position`, at distance D = emitter_distance(light, bounds)
//    from the scene centre along -direction, and is seen from the scene as a sun: each point s
//    of the disk is a PARALLEL light of direction normalize(target - s), target = position +
//    D * direction. The angular diameter is size / D. As size -> 0 this is exactly the hard
//    shadow of the orthographic shadow map (a disk of finite-distance points would instead
//    converge like a point light and cast longer shadows than any orthographic map).
//    Penumbra width, world units, for a blocker h above the receiver along the light:
//    w = h * size / D (similar triangles, the angular form of Fernando 2005, eq. 1).
//  - spot: the disk sits at `position` and faces `direction`; the cone half-angle is spot_angle.
//  - point: light in every direction from `position`; its emitter is a sphere of diameter
//    `size`, which every receiver sees as the disk through `position` facing it. `direction`
//    is not used: outside the scene bounds one frustum is fitted to the scene (shadow_frustum),
//    inside them the shadow map holds six faces (scene/light_faces.h).
//
//   Light l = directional_light_for(bounds, glm::normalize(glm::vec3(-1, -2, -1)), 0.05f);
//   ShadowFrustum f = shadow_frustum(l, bounds);     // for the shadow-map pass
//   auto pts = light_sample_points(l, 256, 0);       // for the references
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "util/error.h"

namespace penumbra::scene {

struct Bounds;

enum class LightType { directional, spot, point };

// "directional", "spot", "point".
const char* light_type_name(LightType type);

// A spot's cone half-angle, degrees: 0 lights nothing, 90 and more is no cone a perspective
// shadow map can hold (light_view_projection's fov is twice the half-angle).
inline constexpr float kMinSpotAngleDegrees = 1.0f;
inline constexpr float kMaxSpotAngleDegrees = 89.0f;
// An error naming the accepted range when `degrees` is outside it (NaN too).
Status check_spot_angle_degrees(float degrees);

struct Light {
  LightType type = LightType::directional;
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit, pointing from the light into the scene
  glm::vec3 position{0.0f, 10.0f, 0.0f};   // emitter disk centre, world units
  float size = 0.5f;                       // emitter disk DIAMETER, world units
  float spot_angle = glm::radians(35.0f);  // spot cone half-angle, radians
  glm::vec3 color{1.0f};                   // linear RGB
  float intensity = 3.0f;                  // multiplier on color (unitless, for the lighting pass)

  float radius() const { return 0.5f * size; }
};

// Whether the light reaches `world` at all: false outside a spot's cone, where the lighting pass
// (passes/lighting) multiplies the shadow by a cone factor of 0, so no mask value shows there.
bool light_reaches(const Light& light, const glm::vec3& world);

// A directional light looking along `direction` at the centre of `bounds`, with its emitter
// plane placed `distance_in_radii` bounding-sphere radii away from the centre and a disk
// diameter of `size_fraction` x the scene's bounding-sphere diameter.
Light directional_light_for(const Bounds& bounds, const glm::vec3& direction,
                            float size_fraction, float distance_in_radii = 2.0f);

// The light's view for a shadow map.
struct ShadowFrustum {
  glm::mat4 view{1.0f};       // world -> light space (looking down -Z along `direction`)
  glm::mat4 proj{1.0f};       // OpenGL clip convention (z in [-1, 1])
  glm::mat4 view_proj{1.0f};
  float near_plane = 0.0f;    // world units from the emitter plane / light position
  float far_plane = 1.0f;
  bool orthographic = true;
  // Orthographic only: width (= height, square) of the frustum in world units, to convert a
  // world size into shadow-map UV: uv = world / width_world. 0 for spot lights.
  float width_world = 0.0f;
  // Perspective only: tan of the half field of view (square frustum); the frustum is
  // 2 * tan_half_fov wide at distance 1. 0 for directional lights.
  float tan_half_fov = 0.0f;
  // A point light that no single frustum can hold (inside the scene bounds, or so close that the
  // frustum would need more than kMaxPointFrustumHalfAngleDeg): the shadow map holds its six
  // faces instead (scene/light_faces.h), and view/proj/view_proj are not used.
  bool six_faces = false;
};

// Widest half-angle of the frustum fitted to the scene for a point light outside the bounds.
inline constexpr float kMaxPointFrustumHalfAngleDeg = 80.0f;

// directional: orthographic, square, fitted to `bounds` as seen from the emitter plane, near/far
// fitted to the bounds' depth range. spot: perspective with fov = 2 * spot_angle, near/far fitted
// to the bounds' distance along `direction` (near >= 1e-3 x far and >= the light's radius). point: when the light is
// outside the bounds, a spot frustum from `position` towards the bounds' centre whose square
// field of view just contains the bounds' corners (the light's `direction` is not used);
// inside them (or with a half-angle above kMaxPointFrustumHalfAngleDeg), `six_faces`.
ShadowFrustum shadow_frustum(const Light& light, const Bounds& bounds);

// Orthonormal basis (tangent, bitangent) of the emitter plane; deterministic for a direction so
// CPU and GPU references place samples identically.
void emitter_basis(const glm::vec3& direction, glm::vec3& tangent, glm::vec3& bitangent);

// M world-space points on the emitter disk: M = rows x cols strata of the unit square (rows =
// the largest divisor of M not above sqrt(M)), each jittered by a hash of (seed, stratum), then
// mapped to the disk with Shirley & Chiu's concentric mapping (area-preserving, so strata stay
// equal-area on the disk). The ONE sampling of the light used by both references. Point lights:
// the disk facing `direction` (the ray tracer turns it to face each receiver: point_light_sample).
std::vector<glm::vec3> light_sample_points(const Light& light, int count, uint32_t seed);

// The same M stratified points on the UNIT disk (light_sample_points scales them by the radius
// and places them in the emitter plane).
std::vector<glm::vec2> unit_disk_samples(int count, uint32_t seed);

// Point lights: the emitter point of unit-disk sample `disk` as seen from `receiver` (the
// sphere's silhouette disk through `position`, facing the receiver).
glm::vec3 point_light_sample(const Light& light, const glm::vec2& disk, const glm::vec3& receiver);

// Directional lights: distance (world units, along `direction`) from the emitter plane to the
// centre of `bounds`, never below the emitter radius. Spot lights: 0 (not used).
float emitter_distance(const Light& light, const Bounds& bounds);

// The scale of a scene's blocker heights: its height (the extent of `bounds` along +Y, up) along
// the light's rays, height / |ray . Y| with |ray . Y| at least kGrazingRaySine: how far a ray
// runs from the top of the scene to its floor. The ray is `direction`, or for a point light the
// way from `position` to the bounds' centre. 1 for empty bounds.
inline constexpr float kGrazingRaySine = 0.1f;
float blocker_height_scale(const Light& light, const Bounds& bounds);

// What a reference traces towards for each light sample (the same M stratified points as
// light_sample_points): spot lights, the point itself (finite ray, `is_point` true);
// directional lights, the unit direction from the light INTO the scene of that sample's
// parallel light (rays from a receiver go along -direction, to infinity); point lights, the
// point of the disk facing `direction` and its unit-disk coordinate `disk`, from which the
// tracer places it on the disk facing each receiver (point_light_sample).
struct LightSample {
  glm::vec3 point{0.0f};      // spot, point: emitter point
  glm::vec3 direction{0.0f};  // directional: unit, light -> scene
  glm::vec2 disk{0.0f};       // unit-disk coordinate of the sample
  bool is_point = true;
};
std::vector<LightSample> light_samples(const Light& light, const Bounds& bounds, int count, uint32_t seed);

}  // namespace penumbra::scene
