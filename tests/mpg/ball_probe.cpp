#include "ball_probe.h"

#include <algorithm>
#include <cmath>

#include "metrics/penumbra_width.h"

namespace penumbra::test {

Result<float> ball_penumbra_width(const metrics::MaskImage& mask, const metrics::MaskImage& ground_y,
                                  float length_px) {
  double sx = 0.0, sy = 0.0, n = 0.0;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      const float h = ground_y.at(x, y);
      if (std::isnan(h) || h > 0.05f || mask.at(x, y) >= 0.5f) continue;
      sx += x + 0.5;
      sy += y + 0.5;
      n += 1.0;
    }
  if (n < 4.0) return make_error("no shadow of the ball on the ground (" + std::to_string(n) + " pixels)");
  const glm::vec2 centre(static_cast<float>(sx / n), static_cast<float>(sy / n));
  return metrics::penumbra_width(mask, centre, {centre.x, std::max(centre.y - length_px, 0.5f)}, 0.1f, 0.9f);
}

}  // namespace penumbra::test
