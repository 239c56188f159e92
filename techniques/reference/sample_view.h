#pragma once
// Where the raster reference looks from: one depth map per light sample (GL-free, glm), the
// same samples the ray tracer traces towards (scene::light_samples, scene/light.h):
//  - a point sample (spot lights) is a point light: a PERSPECTIVE map with its eye at the
//    point, looking along light.direction (orientation of scene::shadow_frustum), with an
//    off-centre frustum fitted to the scene's bounds as seen from the point;
//  - a parallel sample (directional lights, the sun model) is a directional light of its own
//    direction: an ORTHOGRAPHIC map looking along that direction, fitted to the bounds.
//
//   auto samples = scene::light_samples(light, scene.bounds, 1024, 0);
//   SampleView v = sample_view(light, scene.bounds, samples[progressive_index(k, 1024)]);
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/light.h"
#include "scene/scene.h"

namespace penumbra::reference {

// Widest half-angle a sample map covers (a light inside the bounds would need 180 degrees).
// Receivers outside the map count as lit, like receivers outside any shadow frustum.
inline constexpr float kMaxSampleMapHalfAngleDeg = 80.0f;

struct SampleView {
  glm::mat4 view_proj{1.0f};  // world -> clip (OpenGL convention, z in [-1, 1])
  // Width of the map along its wider axis, as frustum_tan * depth + width_world: a texel of an
  // S x S map covers about that / S world units at `depth` from the eye (along its axis).
  float frustum_tan = 0.0f;   // perspective: frustum width at distance 1 (tangent units)
  float width_world = 0.0f;   // orthographic: width in world units
};

SampleView sample_view(const scene::Light& light, const scene::Bounds& bounds, const scene::LightSample& sample);

// The k-th sample to accumulate out of `count` (a permutation of 0..count-1): a stride of about
// count / golden ratio, coprime with count, so any prefix of a progressive run covers the whole
// disk instead of its first rows of strata (partial results are unbiased previews).
int progressive_index(int k, int count);

}  // namespace penumbra::reference
