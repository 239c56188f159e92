#pragma once
// The 2D Poisson disk of the sspcss Poisson filter (section 2: "a 2D random Poisson disk as the
// domain filter"): `count` points in the unit disk, no two closer than the set's size allows,
// by Mitchell's best-candidate algorithm with a fixed seed (the same set every run, so images
// and tests are reproducible). Rotated per pixel in the shader (poisson_taps.glsl).
//
//   std::vector<glm::vec2> taps = sspcss::poisson_disk(32);   // |p| <= 1 for every p
#include <vector>

#include <glm/glm.hpp>

namespace penumbra::sspcss {

std::vector<glm::vec2> poisson_disk(int count);

}  // namespace penumbra::sspcss
