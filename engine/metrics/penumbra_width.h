#pragma once
// Penumbra width measured along a probe line, in pixels.
//
// Definition: sample the mask bilinearly (pixel centres at integer + 0.5) every 0.25 px along the
// segment p0 -> p1 (pixel coordinates). The probe must cross the transition once: if the mask
// is darker at p0 than at p1 it rises, else it falls (the samples are then read from p1 to p0).
// Let s_hi be the first position where the rising profile reaches 0.98 and s_lo the last
// position before s_hi where it is at or below 0.02, each located by linear interpolation
// between samples. The width is s_hi - s_lo, the distance along the segment in pixels.
// A linear ramp of width W (0 -> 1) therefore measures 0.96 W.
//
//   Result<float> w = penumbra_width(reference, {10.5f, 40.5f}, {90.5f, 40.5f});
#include <glm/glm.hpp>

#include "metrics/mask_image.h"
#include "metrics/mask_metrics.h"
#include "util/error.h"

namespace penumbra::metrics {

// Errors when the probe leaves the image or never goes from <= lo to >= hi.
Result<float> penumbra_width(const MaskImage& mask, const glm::vec2& p0, const glm::vec2& p1,
                             float lo = kPenumbraLow, float hi = kPenumbraHigh);

}  // namespace penumbra::metrics
