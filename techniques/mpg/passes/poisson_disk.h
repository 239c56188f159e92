#pragma once
// The precomputed 2D Poisson disk of the multi-pass Gaussian (Cherry & Kooima, section 3.1):
// up to 64 points in [-1, 1]^2, the first fixed at the origin "so the center texel is always
// examined"; the blur pass takes the first `poisson_taps` of them.
#include <array>

#include <glm/glm.hpp>

namespace penumbra::mpg {

inline constexpr int kMaxPoissonPoints = 64;

// The 64 points, generated once (deterministically) by best-candidate sampling (Mitchell 1991):
// point i is, of 32 * i uniform candidates in [-1, 1]^2, the one farthest from points 0..i-1.
// Every prefix of the sequence is then itself well spread (a Poisson-disk-like set whose minimum
// distance shrinks as points are added), which is what taking "the first N" needs.
const std::array<glm::vec2, kMaxPoissonPoints>& poisson_disk();

}  // namespace penumbra::mpg
