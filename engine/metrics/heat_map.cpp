#include "metrics/heat_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

#include "util/png.h"

namespace penumbra::metrics {

glm::u8vec3 heat_color(float e) {
  static const std::array<glm::vec3, 5> stops = {glm::vec3(0, 0, 0), glm::vec3(0, 0, 255), glm::vec3(0, 255, 0),
                                                 glm::vec3(255, 0, 0), glm::vec3(255, 255, 255)};
  if (!(e > 0.0f)) return glm::u8vec3(0);  // also maps NaN to black
  const float x = std::min(e, 1.0f) * 4.0f;
  const int i = std::min(static_cast<int>(x), 3);
  const glm::vec3 c = glm::mix(stops[static_cast<size_t>(i)], stops[static_cast<size_t>(i + 1)], x - static_cast<float>(i));
  return glm::u8vec3(glm::round(c));
}

Result<RgbaImage> error_heat_map(const MaskImage& test, const MaskImage& ref, const CoverageMask& coverage,
                                 float max_error) {
  if (test.width != ref.width || test.height != ref.height || test.pixels.size() != ref.pixels.size() ||
      (!coverage.empty() && coverage.size() != ref.pixels.size()))
    return make_error("heat map inputs differ in size");
  RgbaImage out{ref.width, ref.height, std::vector<uint8_t>(ref.pixels.size() * 4, 255)};
  const float scale = max_error > 0.0f ? 1.0f / max_error : 1.0f;
  for (size_t i = 0; i < ref.pixels.size(); ++i) {
    const glm::u8vec3 c = (!coverage.empty() && !coverage[i])
                              ? glm::u8vec3(40)
                              : heat_color(std::abs(test.pixels[i] - ref.pixels[i]) * scale);
    out.pixels[i * 4 + 0] = c.r, out.pixels[i * 4 + 1] = c.g, out.pixels[i * 4 + 2] = c.b;
  }
  return out;
}

Status write_png(const std::string& path, const RgbaImage& image) {
  if (image.pixels.size() != static_cast<size_t>(image.width) * image.height * 4)
    return make_error("RGBA image has " + std::to_string(image.pixels.size()) + " bytes for " +
                      std::to_string(image.width) + "x" + std::to_string(image.height));
  return penumbra::write_png(path, image.width, image.height, 4, image.pixels.data());
}

Status write_png(const std::string& path, const MaskImage& image) {
  std::vector<uint8_t> grey(image.pixels.size());
  for (size_t i = 0; i < grey.size(); ++i)
    grey[i] = static_cast<uint8_t>(std::lround(std::clamp(std::isfinite(image.pixels[i]) ? image.pixels[i] : 0.0f, 0.0f, 1.0f) * 255.0f));
  if (grey.size() != static_cast<size_t>(image.width) * image.height)
    return make_error("mask image size does not match its pixel count");
  return penumbra::write_png(path, image.width, image.height, 1, grey.data());
}

}  // namespace penumbra::metrics
