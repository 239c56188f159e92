#pragma once
// PNG output through stb_image_write. A failed write leaves no partial file behind.
#include <string>
#include <vector>

#include "util/error.h"

namespace penumbra {

// data: width*height*channels bytes (1 grey, 2 grey+alpha, 3 RGB, 4 RGBA), first row at the top.
Status write_png(const std::string& path, int width, int height, int channels, const unsigned char* data);

// rgba: width*height*4 bytes, first row at the top of the image.
Status write_png_rgba8(const std::string& path, int width, int height,
                       const std::vector<unsigned char>& rgba);

// Single-channel float values mapped linearly from [lo, hi] to grey, first row at the top.
Status write_png_grey(const std::string& path, int width, int height, const std::vector<float>& values,
                      float lo = 0.0f, float hi = 1.0f);

}  // namespace penumbra
