#include "metrics/edge_error.h"

#include <cmath>
#include <string>

#include "metrics/mask_metrics.h"

namespace penumbra::metrics {

CoverageMask edge_band(const MaskImage& ref, const CoverageMask& coverage, float radius) {
  const int w = ref.width, h = ref.height;
  const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
  CoverageMask band(n, 0);
  if (ref.pixels.size() != n || (!coverage.empty() && coverage.size() != n)) return band;
  auto receiver = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && (coverage.empty() || coverage[static_cast<size_t>(y) * w + x]);
  };
  const int r = static_cast<int>(std::floor(radius));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!receiver(x, y)) continue;
      const float v = ref.at(x, y);
      bool edge = v > kPenumbraLow && v < kPenumbraHigh;
      const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
      for (int k = 0; k < 4 && !edge; ++k)
        edge = receiver(nx[k], ny[k]) && (ref.at(nx[k], ny[k]) >= 0.5f) != (v >= 0.5f);
      if (!edge) continue;
      for (int dy = -r; dy <= r; ++dy)  // stamp the disk of the band around this edge pixel
        for (int dx = -r; dx <= r; ++dx)
          if (static_cast<float>(dx * dx + dy * dy) <= radius * radius && receiver(x + dx, y + dy))
            band[static_cast<size_t>(y + dy) * w + x + dx] = 1;
    }
  return band;
}

Result<EdgeError> edge_error(const MaskImage& test, const MaskImage& ref, const CoverageMask& coverage, float radius) {
  const size_t n = static_cast<size_t>(ref.width) * static_cast<size_t>(ref.height);
  if (test.width != ref.width || test.height != ref.height || test.pixels.size() != n || ref.pixels.size() != n ||
      (!coverage.empty() && coverage.size() != n)) {
    Error e = make_error("mask sizes differ: " + std::to_string(test.width) + "x" + std::to_string(test.height) +
                         " vs " + std::to_string(ref.width) + "x" + std::to_string(ref.height) +
                         " (coverage " + std::to_string(coverage.size()) + ")");
    e.where = "edge_error";
    return e;
  }
  const CoverageMask band = edge_band(ref, coverage, radius);
  EdgeError out;
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (!band[i]) continue;
    sum += std::abs(static_cast<double>(test.pixels[i]) - static_cast<double>(ref.pixels[i]));
    ++out.pixels;
  }
  if (out.pixels) out.error = sum / static_cast<double>(out.pixels);
  return out;
}

}  // namespace penumbra::metrics
