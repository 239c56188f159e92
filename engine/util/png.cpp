#include "util/png.h"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "util/file_write.h"

namespace penumbra {

Status write_png(const std::string& path, int width, int height, int channels, const unsigned char* data) {
  if (Status s = check_output_path(path); !s) return s;
  // Write to a temporary name and rename, so a reader never sees a half-written PNG.
  std::string tmp = partial_path(path);
  if (width <= 0 || height <= 0 || !stbi_write_png(tmp.c_str(), width, height, channels, data, width * channels)) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    Error e = make_error("cannot write PNG (" + std::to_string(width) + "x" + std::to_string(height) +
                         "): directory not writable or disk full");
    e.file = path;
    return e;
  }
  return move_into_place(tmp, path);
}

Status write_png_rgba8(const std::string& path, int width, int height,
                       const std::vector<unsigned char>& rgba) {
  if (width <= 0 || height <= 0 || rgba.size() < static_cast<size_t>(width) * height * 4) {
    Error e = make_error("PNG write: image is empty or smaller than its size", ErrorKind::internal);
    e.file = path;
    return e;
  }
  return write_png(path, width, height, 4, rgba.data());
}

Status write_png_grey(const std::string& path, int width, int height, const std::vector<float>& values,
                      float lo, float hi) {
  std::vector<unsigned char> rgba(static_cast<size_t>(width) * height * 4);
  float scale = hi > lo ? 1.0f / (hi - lo) : 0.0f;
  for (size_t i = 0; i < static_cast<size_t>(width) * height && i < values.size(); ++i) {
    float v = std::isfinite(values[i]) ? std::clamp((values[i] - lo) * scale, 0.0f, 1.0f) : 0.0f;
    auto g = static_cast<unsigned char>(std::lround(v * 255.0f));
    rgba[i * 4 + 0] = rgba[i * 4 + 1] = rgba[i * 4 + 2] = g;
    rgba[i * 4 + 3] = 255;
  }
  return write_png_rgba8(path, width, height, rgba);
}

}  // namespace penumbra
