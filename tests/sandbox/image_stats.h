#pragma once
// Reads a PNG back (stb_image) and measures it: a screenshot must not be blank.
#include <stb/stb_image.h>

#include <string>
#include <vector>

namespace penumbra::sandbox_test {

struct ImageStats {
  bool loaded = false;
  int width = 0, height = 0;
  double mean = 0.0;      // of the luminance, 0..255
  double variance = 0.0;  // of the luminance
  double dark = 0.0, bright = 0.0;  // fractions of pixels with luminance < 64 and > 191
};

// Statistics of the columns [x_from * width, width): the sandbox panel covers the left part.
inline ImageStats png_stats(const std::string& path, double x_from = 0.0) {
  ImageStats s;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &s.width, &s.height, &channels, 4);
  if (!data) return s;
  s.loaded = true;
  const int x0 = static_cast<int>(x_from * s.width);
  const size_t n = static_cast<size_t>(s.width - x0) * s.height;
  double sum = 0.0, sum2 = 0.0;
  for (int y = 0; y < s.height; ++y)
  for (int x = x0; x < s.width; ++x) {
    const unsigned char* p = data + 4 * (static_cast<size_t>(y) * s.width + x);
    double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    sum += y;
    sum2 += y * y;
    s.dark += y < 64.0;
    s.bright += y > 191.0;
  }
  stbi_image_free(data);
  s.mean = sum / double(n);
  s.variance = sum2 / double(n) - s.mean * s.mean;
  s.dark /= double(n);
  s.bright /= double(n);
  return s;
}

// An RGBA8 image read back for pixel probes (empty when unreadable).
struct Rgba {
  int width = 0, height = 0;
  std::vector<unsigned char> data;
  const unsigned char* at(int x, int y) const { return data.data() + 4 * (static_cast<size_t>(y) * width + x); }
  double luminance(int x, int y) const {
    const unsigned char* p = at(x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  }
};

inline Rgba read_rgba(const std::string& path) {
  Rgba r;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &r.width, &r.height, &channels, 4);
  if (!data) return r;
  r.data.assign(data, data + 4 * static_cast<size_t>(r.width) * r.height);
  stbi_image_free(data);
  return r;
}

}  // namespace penumbra::sandbox_test
