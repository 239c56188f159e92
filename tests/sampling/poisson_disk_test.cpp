// passes/sampling/poisson_disk.h: determinism, the domain, and the spacing that makes a tap set
// a Poisson disk, for every prefix of the sequence, in both domains and with the options the
// techniques use (sspcss: unit disk; mpg: the square, first point at the origin). No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "passes/sampling/poisson_disk.h"

namespace penumbra::passes {
namespace {

struct Case {
  std::string name;
  PoissonDiskOptions options;
  float area;  // of the domain
};

const Case kCases[] = {
    {"unit_disk", {.seed = 0x2545F491u}, 3.14159265f},
    {"square_from_origin",
     {.seed = 0x9E3779B9u, .domain = SampleDomain::square, .candidates_per_point = 32, .first_at_origin = true},
     4.0f},
};

float closest_pair(const std::vector<glm::vec2>& p, size_t n) {
  float closest = 1e9f;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < i; ++j) closest = std::min(closest, glm::distance(p[i], p[j]));
  return closest;
}

TEST(PoissonDisk, SameSeedSameTapsAnotherSeedOtherTaps) {
  for (const Case& c : kCases) {
    EXPECT_EQ(poisson_disk(32, c.options), poisson_disk(32, c.options)) << c.name;
    PoissonDiskOptions other = c.options;
    other.seed ^= 0x1234u;
    EXPECT_NE(poisson_disk(32, c.options), poisson_disk(32, other)) << c.name;
  }
}

// A longer set starts with the shorter one, so a filter may take "the first N" of it.
TEST(PoissonDisk, ASetIsThePrefixOfALongerOne) {
  for (const Case& c : kCases) {
    const std::vector<glm::vec2> all = poisson_disk(64, c.options), some = poisson_disk(20, c.options);
    ASSERT_EQ(all.size(), 64u);
    ASSERT_EQ(some.size(), 20u);
    EXPECT_TRUE(std::equal(some.begin(), some.end(), all.begin())) << c.name;
  }
  EXPECT_TRUE(poisson_disk(0).empty());
  EXPECT_TRUE(poisson_disk(-3).empty());
}

TEST(PoissonDisk, EveryPointLiesInsideItsDomain) {
  for (const glm::vec2& p : poisson_disk(64, kCases[0].options)) EXPECT_LE(glm::length(p), 1.0f + 1e-6f);
  const std::vector<glm::vec2> square = poisson_disk(64, kCases[1].options);
  EXPECT_EQ(square[0], glm::vec2(0.0f));
  for (const glm::vec2& p : square) {
    EXPECT_LE(std::abs(p.x), 1.0f);
    EXPECT_LE(std::abs(p.y), 1.0f);
  }
}

// The minimum distance: n points spread evenly over a domain of area A are about sqrt(A / n)
// apart; every prefix of a best-candidate set keeps its closest pair above half of that
// (measured 0.8-1.5 of it), where n uniform random points typically have a pair ~10x closer.
TEST(PoissonDisk, EveryPrefixKeepsItsPointsApart) {
  for (const Case& c : kCases) {
    const std::vector<glm::vec2> p = poisson_disk(64, c.options);
    for (size_t n : {2, 4, 8, 16, 20, 32, 64}) {
      const float spacing = std::sqrt(c.area / static_cast<float>(n));
      const float closest = closest_pair(p, n);
      std::printf("[ measure  ] %s, %zu points: closest pair %.3f = %.2f x sqrt(A / n)\n", c.name.c_str(), n,
                  closest, closest / spacing);
      EXPECT_GT(closest, 0.5f * spacing) << c.name << ", " << n << " points";
    }
  }
}

}  // namespace
}  // namespace penumbra::passes
