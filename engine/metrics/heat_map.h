#pragma once
// Error heat maps and PNG output.
//
// Colour map of e = |test - reference| / max_error, clamped to [0, 1], piecewise linear through
//   0 black (0,0,0) -> 0.25 blue (0,0,255) -> 0.5 green (0,255,0) -> 0.75 red (255,0,0) -> 1 white.
// Background pixels (coverage 0) are dark grey (40,40,40), alpha is 255 everywhere.
//
//   auto map = error_heat_map(mask, ref, coverage, 0.25f);
//   if (Status s = write_png("out/err.png", *map); !s) spdlog::error("{}", s.error().to_string());
#include <string>

#include <glm/glm.hpp>

#include "metrics/mask_image.h"
#include "util/error.h"

namespace penumbra::metrics {

glm::u8vec3 heat_color(float normalized_error);

Result<RgbaImage> error_heat_map(const MaskImage& test, const MaskImage& reference,
                                 const CoverageMask& coverage = {}, float max_error = 1.0f);

// Writes 8-bit RGBA. On failure the partial file is removed and the Error names the path.
Status write_png(const std::string& path, const RgbaImage& image);
// Writes 8-bit grey: value clamped to [0, 1] -> 0..255.
Status write_png(const std::string& path, const MaskImage& image);

}  // namespace penumbra::metrics
