#include "techniques/mpg/passes/poisson_disk.h"

#include <cstdint>
#include <limits>

namespace penumbra::mpg {
namespace {

// xorshift32: a fixed, platform-independent sequence (std:: distributions are not portable).
struct Xorshift {
  std::uint32_t state = 0x9E3779B9u;
  float unit() {  // uniform in [-1, 1], both ends included
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return static_cast<float>(state >> 8) / static_cast<float>((1u << 24) - 1u) * 2.0f - 1.0f;
  }
};

std::array<glm::vec2, kMaxPoissonPoints> best_candidate_points() {
  std::array<glm::vec2, kMaxPoissonPoints> points{};
  points[0] = glm::vec2(0.0f);  // section 3.1: the centre texel is always examined
  Xorshift rng;
  for (int i = 1; i < kMaxPoissonPoints; ++i) {
    glm::vec2 best(0.0f);
    float best_distance = -1.0f;
    for (int c = 0; c < 32 * i; ++c) {
      glm::vec2 candidate(rng.unit(), rng.unit());
      float nearest = std::numeric_limits<float>::max();
      for (int j = 0; j < i; ++j) {
        glm::vec2 d = candidate - points[static_cast<size_t>(j)];
        nearest = std::min(nearest, glm::dot(d, d));
      }
      if (nearest > best_distance) best_distance = nearest, best = candidate;
    }
    points[static_cast<size_t>(i)] = best;
  }
  return points;
}

}  // namespace

const std::array<glm::vec2, kMaxPoissonPoints>& poisson_disk() {
  static const std::array<glm::vec2, kMaxPoissonPoints> points = best_candidate_points();
  return points;
}

}  // namespace penumbra::mpg
