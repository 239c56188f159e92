#include "gl/texture_png.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/png.h"

namespace penumbra::gl {

Status write_texture_png(const Texture& texture, const std::string& path) {
  const FormatInfo& f = texture.info();
  const int w = texture.width(), h = texture.height();
  std::vector<float> texels = texture.read();
  float lo = 0.0f, hi = 1.0f;
  if (f.is_depth) {
    lo = std::numeric_limits<float>::max();
    hi = std::numeric_limits<float>::lowest();
    for (float v : texels)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    if (lo >= hi) lo = 0.0f, hi = 1.0f;
  }
  std::vector<unsigned char> rgba(static_cast<size_t>(w) * h * 4, 255);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float* t = &texels[(static_cast<size_t>(h - 1 - y) * w + x) * f.channels];
      unsigned char* out = &rgba[(static_cast<size_t>(y) * w + x) * 4];
      for (int c = 0; c < 3; ++c) {
        float v = f.channels == 1 ? t[0] : (c < f.channels ? t[c] : 0.0f);
        v = (v - lo) / (hi - lo);
        out[c] = static_cast<unsigned char>(std::lround(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) * 255.0f));
      }
    }
  }
  return write_png_rgba8(path, w, h, rgba);
}

}  // namespace penumbra::gl
