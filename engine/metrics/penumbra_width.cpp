#include "metrics/penumbra_width.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace penumbra::metrics {

static float sample_bilinear(const MaskImage& m, glm::vec2 p) {
  const glm::vec2 q = p - 0.5f;  // pixel centres at integer + 0.5
  const int x0 = static_cast<int>(std::floor(q.x)), y0 = static_cast<int>(std::floor(q.y));
  const float fx = q.x - static_cast<float>(x0), fy = q.y - static_cast<float>(y0);
  auto at = [&](int x, int y) { return m.at(std::clamp(x, 0, m.width - 1), std::clamp(y, 0, m.height - 1)); };
  const float top = at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx;
  const float bottom = at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx;
  return top * (1 - fy) + bottom * fy;
}

Result<float> penumbra_width(const MaskImage& mask, const glm::vec2& p0, const glm::vec2& p1, float lo, float hi) {
  auto inside = [&](glm::vec2 p) {
    return p.x >= 0 && p.y >= 0 && p.x <= static_cast<float>(mask.width) && p.y <= static_cast<float>(mask.height);
  };
  const auto fail = [&](const std::string& msg) {
    Error e = make_error(msg);
    e.where = "penumbra probe (" + std::to_string(p0.x) + "," + std::to_string(p0.y) + ")->(" +
              std::to_string(p1.x) + "," + std::to_string(p1.y) + ")";
    return e;
  };
  if (mask.width <= 0 || mask.height <= 0 || !inside(p0) || !inside(p1)) return fail("probe leaves the image");
  const float length = glm::length(p1 - p0);
  constexpr float kStep = 0.25f;  // pixels
  const int n = std::max(2, static_cast<int>(std::ceil(length / kStep)) + 1);
  std::vector<float> v(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
    v[static_cast<size_t>(i)] = sample_bilinear(mask, p0 + (p1 - p0) * (static_cast<float>(i) / (n - 1)));
  if (v.front() > v.back()) std::reverse(v.begin(), v.end());  // make the profile rising
  const float step = length / static_cast<float>(n - 1);

  size_t i_hi = 0;
  while (i_hi < v.size() && v[i_hi] < hi) ++i_hi;
  if (i_hi == v.size()) return fail("mask never reaches " + std::to_string(hi) + " along the probe");
  size_t i_lo = i_hi;
  while (i_lo > 0 && v[i_lo] > lo) --i_lo;
  if (v[i_lo] > lo) return fail("mask is never at or below " + std::to_string(lo) + " before it turns lit");
  // Sub-sample crossing positions by linear interpolation between neighbouring samples.
  auto crossing = [&](size_t a, float level) {  // level lies between v[a] and v[a + 1]
    const float d = v[a + 1] - v[a];
    const float t = d != 0.0f ? std::clamp((level - v[a]) / d, 0.0f, 1.0f) : 0.0f;
    return (static_cast<float>(a) + t) * step;
  };
  const float s_hi = i_hi > 0 ? crossing(i_hi - 1, hi) : 0.0f;
  const float s_lo = i_lo + 1 < v.size() ? crossing(i_lo, lo) : static_cast<float>(i_lo) * step;
  return std::max(0.0f, s_hi - s_lo);
}

}  // namespace penumbra::metrics
