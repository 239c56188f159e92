#pragma once
// The pixel inspector (RenderDoc-style): the value under a frame pixel of whatever is shown
// there (the viewed resource, full or inset, or the final image: the colour of the compare side
// under it, or |a - b| in the error view), through the same mapping the composer draws with
// (view_mapping.h: zoom, pan, aspect); and the auto range of the viewed resource.
//
//   auto r = inspect_pixel(controller, {x, y});   // frame pixel, origin top-left
//   if (r && r->texel) show(r->source, *r->texel, r->value);
#include <array>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "sandbox/controller.h"

namespace penumbra::sandbox {

struct PixelReadout {
  std::string source;  // resource name, "color (A)", "color (B)", "color (reference)" or "A - B"
  glm::ivec2 pixel{0};                // frame pixel, origin top-left
  // Texel of the inspected image, origin top-left like the pixel (row 0 is the image's top row,
  // as in a saved PNG); none outside the image.
  std::optional<glm::ivec2> texel;
  int channels = 0;
  std::array<float, 4> value{};       // as stored
  std::optional<float> linear_depth;  // screen depth as view distance (world units)
};

Result<PixelReadout> inspect_pixel(SandboxController& c, glm::ivec2 pixel);
// "shadow_mask (120, 45) = 0.25" / "color (A) (3, 4) = 0.51 0.48 0.40 1"; "" outside the image.
std::string readout_text(const PixelReadout& r);

// The readout as JSON {"source", "pixel", "texel" (null outside), "channels", "value": [...],
// "linear_depth" (screen depth only)} into `path` (the scripts' `inspect` step).
Status write_inspection(SandboxController& c, int x, int y, const std::string& path);

}  // namespace penumbra::sandbox
