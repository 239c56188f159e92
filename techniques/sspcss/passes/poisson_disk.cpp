#include "techniques/sspcss/passes/poisson_disk.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace penumbra::sspcss {
namespace {

// xorshift32 (Marsaglia 2003): small, deterministic on every platform.
struct Random {
  std::uint32_t state = 0x2545F491u;
  float next() {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return static_cast<float>(state >> 8) * (1.0f / 16777216.0f);
  }
};

// Uniform in the unit disk (area-preserving: r = sqrt(u)).
glm::vec2 disk_point(Random& random) {
  const float r = std::sqrt(random.next());
  const float phi = 6.28318530718f * random.next();
  return r * glm::vec2(std::cos(phi), std::sin(phi));
}

}  // namespace

std::vector<glm::vec2> poisson_disk(int count) {
  std::vector<glm::vec2> points;
  if (count <= 0) return points;
  Random random;
  points.reserve(static_cast<size_t>(count));
  points.push_back(disk_point(random));
  // Mitchell 1991, best candidate: of k * n fresh candidates keep the one farthest from the n
  // points already chosen (k = 10: close to a true Poisson disk, instant for 64 points).
  constexpr int kCandidatesPerPoint = 10;
  while (static_cast<int>(points.size()) < count) {
    glm::vec2 best(0.0f);
    float best_distance = -1.0f;
    const int candidates = kCandidatesPerPoint * static_cast<int>(points.size());
    for (int c = 0; c < candidates; ++c) {
      const glm::vec2 candidate = disk_point(random);
      float nearest = std::numeric_limits<float>::max();
      for (const glm::vec2& p : points) nearest = std::min(nearest, glm::dot(candidate - p, candidate - p));
      if (nearest > best_distance) {
        best_distance = nearest;
        best = candidate;
      }
    }
    points.push_back(best);
  }
  return points;
}

}  // namespace penumbra::sspcss
