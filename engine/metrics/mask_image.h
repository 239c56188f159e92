#pragma once
// Single-channel float images (a shadow_mask: visibility, 1 = lit, 0 = umbra) and RGBA8 images
// for heat maps. Rows top to bottom, pixel (x, y) at index y * width + x.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace penumbra::metrics {

struct MaskImage {
  int width = 0;
  int height = 0;
  std::vector<float> pixels;  // width * height

  MaskImage() = default;
  MaskImage(int w, int h, float fill = 0.0f)
      : width(w), height(h), pixels(static_cast<size_t>(w) * static_cast<size_t>(h), fill) {}
  float& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
  float at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

// Which pixels are receivers (1) and which are background (0); empty = every pixel counts.
using CoverageMask = std::vector<uint8_t>;

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> pixels;  // width * height * 4
};

}  // namespace penumbra::metrics
