#include "ball_probe.h"

#include <cmath>

namespace penumbra::test {

std::optional<Probe> ball_shadow_probe(const metrics::MaskImage& mask, const metrics::MaskImage& ground_y,
                                       float length_px) {
  double sx = 0, sy = 0, n = 0;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      float gy = ground_y.at(x, y);
      if (std::isnan(gy) || gy > 0.05f || mask.at(x, y) >= 0.5f) continue;
      sx += x + 0.5;
      sy += y + 0.5;
      n += 1;
    }
  if (n < 4) return std::nullopt;
  glm::vec2 c(static_cast<float>(sx / n), static_cast<float>(sy / n));
  glm::vec2 end(c.x, std::max(c.y - length_px, 0.5f));
  return Probe{c, end};
}

}  // namespace penumbra::test
