#include "techniques/mpg/passes/multipass_kernel.h"

#include <algorithm>
#include <cmath>

#include "passes/sampling/poisson_disk.h"

namespace penumbra::mpg {

const std::vector<glm::vec2>& poisson_points() {
  static const std::vector<glm::vec2> points =
      passes::poisson_disk(kMaxPoissonPoints, {.seed = 0x9E3779B9u, .domain = passes::SampleDomain::square,
                                               .candidates_per_point = 32, .first_at_origin = true});
  return points;
}

int pass_kernel_size(bool progressive, int iteration, int max_kernel) {
  if (!progressive) return max_kernel;
  return std::min(3 + 2 * iteration, max_kernel);
}

float gaussian_weight(glm::vec2 offset_px, int size) {
  const float sigma = static_cast<float>(size) / 3.0f;  // pixels
  return std::exp(-glm::dot(offset_px, offset_px) / (2.0f * sigma * sigma));
}

std::vector<Tap> kernel_taps(KernelSampling sampling, int count, int size, int iteration) {
  std::vector<Tap> taps;
  const float half = 0.5f * static_cast<float>(size - 1);  // pixels from the centre to the edge texel
  if (sampling == KernelSampling::dense) {
    const int r = (size - 1) / 2;
    for (int y = -r; y <= r; ++y)
      for (int x = -r; x <= r; ++x) taps.push_back({glm::vec2(x, y), 0.0f});
  } else {
    const int n = std::clamp(count, 1, kMaxPoissonPoints);
    const float a = 2.39996323f * static_cast<float>(iteration);
    const glm::mat2 rot(std::cos(a), std::sin(a), -std::sin(a), std::cos(a));
    for (int i = 0; i < n; ++i) taps.push_back({rot * poisson_points()[static_cast<size_t>(i)] * half, 0.0f});
  }
  double sum = 0.0;
  for (Tap& t : taps) sum += t.weight = gaussian_weight(t.offset, size);
  for (Tap& t : taps) t.weight = static_cast<float>(t.weight / sum);
  return taps;
}

double kernel_variance(const std::vector<Tap>& taps) {
  glm::dvec2 mean(0.0);
  for (const Tap& t : taps) mean += static_cast<double>(t.weight) * glm::dvec2(t.offset);
  double variance = 0.0;
  for (const Tap& t : taps) {
    glm::dvec2 d = glm::dvec2(t.offset) - mean;
    glm::dvec2 f = glm::dvec2(t.offset) - glm::floor(glm::dvec2(t.offset));
    variance += t.weight * (0.5 * glm::dot(d, d) + 0.5 * (f.x * (1.0 - f.x) + f.y * (1.0 - f.y)));
  }
  return variance;
}

std::vector<float> cumulative_pass_variance(KernelSampling sampling, int count, bool progressive,
                                            int max_kernel, int max_passes) {
  std::vector<float> cumulative(static_cast<size_t>(max_passes) + 1, 0.0f);
  double total = 0.0;
  for (int i = 0; i < max_passes; ++i) {
    total += kernel_variance(kernel_taps(sampling, count, pass_kernel_size(progressive, i, max_kernel), i));
    cumulative[static_cast<size_t>(i) + 1] = static_cast<float>(total);
  }
  return cumulative;
}

}  // namespace penumbra::mpg
