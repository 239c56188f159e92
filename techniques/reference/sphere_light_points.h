#pragma once
// The raster reference's sample points for a point light (a sphere of radius light.radius()).
// The ray tracer draws each receiver's samples on the sphere's disk through its centre facing
// that receiver (scene::point_light_sample), which one depth map per sample cannot do: a map
// is rendered from one point for every receiver. These points fill the ball with density
// proportional to 1 / sqrt(1 - (s / r)^2) at distance s from the centre: projected along ANY
// direction, that density is uniform over the disk of radius r (Abel's integral: the chord
// through the ball at disk radius p integrates 1 / sqrt(1 - p^2 - z^2) over z to pi for every p).
// So every receiver sees them spread uniformly over its own disk, as the tracer's points are.
// A receiver at distance D sees the disk in perspective, not parallel: a point nearer to it by
// z lands (D / (D - z)) farther out, which cancels to first order between the near and far
// halves of the ball (an error of order (r / D)^2).
//
//   std::vector<glm::vec3> points = sphere_light_points(light, 1024, seed);
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/light.h"

namespace penumbra::reference {

// `count` points in the light's ball (all at its centre when it has no size), a low-discrepancy
// sequence (Halton in bases 2, 3 and 5) rotated by `seed`: any prefix covers the ball evenly.
std::vector<glm::vec3> sphere_light_points(const scene::Light& light, int count, uint32_t seed);

}  // namespace penumbra::reference
