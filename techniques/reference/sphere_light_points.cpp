#include "sphere_light_points.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace penumbra::reference {
namespace {

double radical_inverse(uint32_t i, uint32_t base) {
  double inverse = 0.0, digit = 1.0 / base;
  for (; i > 0; i /= base, digit /= base) inverse += static_cast<double>(i % base) * digit;
  return inverse;
}

// A seed's rotation of one dimension of the sequence (Cranley-Patterson), in [0, 1).
double rotation(uint32_t seed, uint32_t dimension) {
  uint64_t z = (static_cast<uint64_t>(seed) << 8 | dimension) + 0x9E3779B97F4A7C15ull;  // splitmix64
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

double rotated(double u, double by) { return std::fmod(u + by, 1.0); }

// The radius fraction s = sin(theta) with P(below s) = w: the density s^2 / sqrt(1 - s^2) of the
// header's ball (the shell's area s^2 times the density) has the distribution function
// (2 / pi) (theta - sin theta cos theta), increasing in theta on [0, pi / 2]: bisected.
double radius_fraction(double w) {
  double lo = 0.0, hi = std::numbers::pi / 2.0;
  for (int i = 0; i < 48; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double f = (2.0 / std::numbers::pi) * (mid - std::sin(mid) * std::cos(mid));
    (f < w ? lo : hi) = mid;
  }
  return std::sin(0.5 * (lo + hi));
}

}  // namespace

std::vector<glm::vec3> sphere_light_points(const scene::Light& light, int count, uint32_t seed) {
  std::vector<glm::vec3> points;
  if (count <= 0) return points;
  points.reserve(static_cast<size_t>(count));
  const double radius = light.radius();
  const double r2 = rotation(seed, 0), r3 = rotation(seed, 1), r5 = rotation(seed, 2);
  for (int k = 0; k < count; ++k) {
    const uint32_t i = static_cast<uint32_t>(k) + 1u;
    const double cos_polar = 1.0 - 2.0 * rotated(radical_inverse(i, 2), r2);
    const double azimuth = 2.0 * std::numbers::pi * rotated(radical_inverse(i, 3), r3);
    const double sin_polar = std::sqrt(std::max(0.0, 1.0 - cos_polar * cos_polar));
    const glm::dvec3 direction(sin_polar * std::cos(azimuth), sin_polar * std::sin(azimuth), cos_polar);
    const double s = radius * radius_fraction(rotated(radical_inverse(i, 5), r5));
    points.push_back(light.position + glm::vec3(s * direction));
  }
  return points;
}

}  // namespace penumbra::reference
