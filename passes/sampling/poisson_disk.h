#pragma once
// Poisson-disk tap sets for the techniques' filters (no GL): a progressive best-candidate
// sequence (Mitchell 1991) from a fixed seed, so a technique gets the same taps every run and
// every prefix of the sequence is itself well spread (a filter may take "the first N").
// sampling.glsl (beside this file) holds the GPU side: per-pixel rotation noise and the Vogel
// disk.
//
//   // sspcss: 32 taps in the unit disk
//   std::vector<glm::vec2> taps = passes::poisson_disk(32, {.seed = 0x2545F491u});
//   // mpg: 64 points in [-1, 1]^2, the first at the origin
//   passes::poisson_disk(64, {.seed = 0x9E3779B9u, .domain = passes::SampleDomain::square,
//                             .candidates_per_point = 32, .first_at_origin = true});
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace penumbra::passes {

enum class SampleDomain {
  unit_disk,  // |p| <= 1, candidates area-uniform (r = sqrt(u))
  square,     // [-1, 1]^2
};

struct PoissonDiskOptions {
  // xorshift32 state (non-zero): a technique fixes its own, so its tap set never changes.
  std::uint32_t seed = 0x2545F491u;
  SampleDomain domain = SampleDomain::unit_disk;
  // Point i is the best of candidates_per_point * i uniform candidates: the one farthest from
  // points 0..i-1. More candidates, closer to a true Poisson disk (10 already is, for 64 points).
  int candidates_per_point = 10;
  // Point 0 at (0, 0) instead of a random one (a filter that must always read the centre texel).
  bool first_at_origin = false;
};

// The first `count` points of the sequence (none for count <= 0). Deterministic on every
// platform: std:: distributions are not portable, xorshift32 and the arithmetic here are.
std::vector<glm::vec2> poisson_disk(int count, const PoissonDiskOptions& options = {});

}  // namespace penumbra::passes
