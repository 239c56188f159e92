#pragma once
// Cascaded shadow maps for a directional light: the camera's view range split in up to four
// slices, each shadowed by an orthographic view of its own laid out as a tile of the one shadow
// map (a 2048^2 map holds four 1024^2 cascades: the same texels as one map over the scene).
//
// - Splits: the practical split scheme (Zhang et al. 2006, "Parallel-split shadow maps"),
//   z_i = lambda n (f/n)^(i/N) + (1 - lambda) (n + (f - n) i/N): lambda = 1 logarithmic (even
//   texel density in perspective), 0 linear. n, f: the camera's near plane and the farthest
//   corner of the scene in front of it (nothing beyond casts or receives), rounded up to a step
//   of 2^(1/8) so that the slices stay put while the camera moves (within the camera's far plane).
// - Stable (no shimmer under camera motion): each cascade is a square as wide as the sphere
//   around its slice, whose size depends on the slice's shape alone, not on where the camera
//   looks; its centre is snapped to whole texels of its tile, so a moving camera moves it by
//   whole texels and every texel rasterises the same geometry. A cascade wider than the
//   scene's own map is that map's square (it is no finer).
// - Every cascade shares the scene map's light view and depth range, so a depth means the same
//   distance in every tile (shadow_common.glsl's light_distance()), and only a texel's width
//   changes from one cascade to the next.
// - Which cascade a receiver reads: the first whose square holds it at least a margin
//   (kCascadeMargin of the square) from its edge, so filter kernels of that size stay in the
//   tile; within a blend band before that margin it dithers to the next cascade, a share of its
//   points that grows towards the margin (no pass blends two results: a multi-pass technique
//   would run each of its passes twice there). Both are fractions of a square's half side.
//
//   Result<ShadowCascades> c = shadow_cascades(frame.shadow, camera, aspect, bounds, settings, map_size);
#include <array>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/light.h"
#include "scene/light_faces.h"
#include "scene/scene.h"
#include "util/error.h"

namespace penumbra::scene {

inline constexpr int kMaxCascades = 4;
// Each cascade's square is its slice's sphere widened by this fraction of its diameter on every
// side: the room a filter kernel has before the receiver moves to the next cascade.
inline constexpr float kCascadeMargin = 0.1f;
// That margin as a fraction of the square's half side (shadow_common.glsl's u_cascade_margin).
inline constexpr float kCascadeMarginOfHalfSide = 2.0f * kCascadeMargin / (1.0f + 2.0f * kCascadeMargin);

struct CascadeSettings {
  int count = 1;              // 1 (one map over the scene) to kMaxCascades
  float split_lambda = 0.9f;  // practical split scheme: 0 linear, 1 logarithmic (avenue: 0.9 best of 0.5-1)
  float blend = 0.1f;         // band over which a cascade dithers to the next, fraction of its half side
  bool tint = false;          // debug view: the lit image tinted by the cascade each pixel reads
};

// Errors name the setting and its range: count outside 1..4, lambda outside [0, 1], blend
// outside [0, 0.5].
Status check_cascade_settings(const CascadeSettings& settings);

// The count + 1 split distances (view depth, world units) from near to far.
std::array<float, kMaxCascades + 1> cascade_splits(float near_plane, float far_plane, int count, float lambda);

struct ShadowCascades {
  int count = 1;                               // 1: the scene's one map; no tiles
  std::array<LightFace, kMaxCascades> tiles{};  // view_proj (world -> clip) and the tile in the map
  std::array<float, kMaxCascades> width_world{};  // each square's side, world units
  std::array<float, kMaxCascades + 1> splits{};   // the view depths the slices were cut at
  float blend = 0.0f;
  bool tint = false;  // CascadeSettings::tint
};

// The cascades of a directional light's `one_map` frustum (shadow_frustum) for the camera at
// `aspect`, in a square map of `map_size` texels (tiles of map_size / 2). Errors: the settings
// (check_cascade_settings), cascades for a light that is not directional.
Result<ShadowCascades> shadow_cascades(const Light& light, const ShadowFrustum& one_map, const Camera& camera,
                                       float aspect, const Bounds& bounds, const CascadeSettings& settings,
                                       int map_size);

// The cascade a world position is read in, without the blend band's dither (as with blend 0):
// the first whose square holds it the margin inside its edge; count where none holds it. The
// same rule as cascade_of() in passes/common/shadow_common.glsl.
int cascade_of(const ShadowCascades& cascades, const glm::vec3& world);

}  // namespace penumbra::scene
