#include "passes/sampling/poisson_disk.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penumbra::passes {
namespace {

// xorshift32 (Marsaglia 2003): small, and the same sequence on every platform.
struct Xorshift32 {
  std::uint32_t state;
  float next() {  // uniform in [0, 1)
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return static_cast<float>(state >> 8) * (1.0f / 16777216.0f);
  }
};

glm::vec2 candidate(Xorshift32& random, SampleDomain domain) {
  if (domain == SampleDomain::square) {
    // y drawn before x: the order mpg's tap set was first generated in.
    const float y = 2.0f * random.next() - 1.0f;
    return {2.0f * random.next() - 1.0f, y};
  }
  const float r = std::sqrt(random.next());  // area-uniform in the disk
  const float phi = 6.28318530718f * random.next();
  return r * glm::vec2(std::cos(phi), std::sin(phi));
}

}  // namespace

std::vector<glm::vec2> poisson_disk(int count, const PoissonDiskOptions& options) {
  std::vector<glm::vec2> points;
  if (count <= 0) return points;
  Xorshift32 random{options.seed};
  points.reserve(static_cast<size_t>(count));
  points.push_back(options.first_at_origin ? glm::vec2(0.0f) : candidate(random, options.domain));
  while (static_cast<int>(points.size()) < count) {
    glm::vec2 best(0.0f);
    float best_distance = -1.0f;
    const int candidates = options.candidates_per_point * static_cast<int>(points.size());
    for (int c = 0; c < candidates; ++c) {
      const glm::vec2 q = candidate(random, options.domain);
      float nearest = std::numeric_limits<float>::max();
      for (const glm::vec2& p : points) nearest = std::min(nearest, glm::dot(q - p, q - p));
      if (nearest > best_distance) {
        best_distance = nearest;
        best = q;
      }
    }
    points.push_back(best);
  }
  return points;
}

}  // namespace penumbra::passes
