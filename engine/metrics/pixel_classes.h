#pragma once
// Which receiver pixels a penumbra metric can judge. Defined from the reference and the frame's
// G-buffer alone (never from a technique's output), so no class favours a technique:
//   geometric_edge  within kGeometricEdgeRadius px of a depth or normal discontinuity of the
//                   G-buffer, of the background, or of a self-shadowing terminator (the sign of
//                   N·L changes between neighbours): where a shadow map cannot resolve a surface
//                   shadowing itself, whatever the filter (docs/evaluation.md "Pixel classes")
//   soft_penumbra   otherwise, reference strictly between kPenumbraLow and kPenumbraHigh
//   lit, umbra      otherwise, reference at or above kPenumbraHigh / at or below kPenumbraLow
//   outside_light   receivers the light does not reach (outside a spot's cone: scene::
//                   light_reaches), whatever the above: the lighting shows no mask value there,
//                   so no statistic judges them (judged_pixels)
//
//   ReceiverGeometry g{w, h, view_depth, normals, facing};   // facing = N · (direction to light)
//   PixelClasses c = classify_pixels(reference, coverage, &g);
//   PenumbraReliability r = penumbra_reliability(c);   // r.reliable, r.reason
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "metrics/mask_image.h"
#include "scene/light.h"

namespace penumbra::metrics {

// Reference values strictly inside (low, high) are penumbra.
inline constexpr float kPenumbraLow = 0.02f;
inline constexpr float kPenumbraHigh = 0.98f;

enum class PixelClass : uint8_t { background, lit, umbra, soft_penumbra, geometric_edge, outside_light };
const char* pixel_class_name(PixelClass c);

// Pixels (Chebyshev distance) a discontinuity's class reaches.
inline constexpr int kGeometricEdgeRadius = 2;
// A depth discontinuity: the second difference of inverse view depth across a pixel (zero on any
// plane, whose inverse depth is linear in screen space) above this share of its inverse depth.
inline constexpr float kDepthCreaseShare = 0.02f;
// A normal discontinuity: neighbours' normals more than 30 degrees apart.
inline constexpr float kNormalCreaseCos = 0.866f;

// The frame's receivers, rows top to bottom like the masks (width * height entries each).
struct ReceiverGeometry {
  int width = 0, height = 0;
  std::vector<float> view_depth;    // > 0 on receivers
  std::vector<glm::vec3> normals;   // unit, world space
  std::vector<float> facing;        // N · (unit direction to the light); <= 0: faces away
  std::vector<uint8_t> reached;     // scene::light_reaches (0 outside a spot's cone)
};

// From world positions with their view depth in w (0 on background) and world normals, rows top
// to bottom (exec::read_positions, RowOrder::top_down): facing towards `light`.
ReceiverGeometry receiver_geometry(int width, int height, const std::vector<glm::vec4>& positions,
                                   const std::vector<glm::vec3>& normals, const scene::Light& light);

struct PixelClasses {
  int width = 0, height = 0;
  std::vector<PixelClass> classes;
  size_t count(PixelClass c) const;
};

// Classes of every pixel; without geometry (nullptr) no pixel is a geometric edge or outside the
// light. Sizes must match (checked by the callers that build the inputs; mismatched inputs give
// an empty result).
PixelClasses classify_pixels(const MaskImage& reference, const CoverageMask& coverage,
                             const ReceiverGeometry* geometry = nullptr);

// The pixels every statistic judges: receivers but those outside the light.
CoverageMask judged_pixels(const PixelClasses& classes);

// Whether the soft penumbra can carry a verdict: at least kMinPenumbraShare of the receivers, and
// not mostly isolated pixels (more than half of its 8-connected groups a single pixel).
inline constexpr double kMinPenumbraShare = 0.01;
struct PenumbraReliability {
  bool reliable = false;
  std::string reason;  // empty when reliable
  size_t groups = 0, single_pixel_groups = 0;
};
PenumbraReliability penumbra_reliability(const PixelClasses& classes);

// A picture of the classes (docs/evaluation.md's colours): lit white, umbra black, soft penumbra
// orange, geometric edge blue, background grey, outside the light dark blue-grey.
RgbaImage pixel_class_image(const PixelClasses& classes);

}  // namespace penumbra::metrics
