#pragma once
// Edge error: how well a mask reproduces the reference's shadow EDGES, the quantity a hard-shadow
// technique (hard, esm) is judged on against the exact hard reference (light size 0), where RMSE
// over the whole image is dominated by the area far from any edge.
//
//   edge pixel  a receiver pixel whose reference value is fractional (kPenumbraLow < ref <
//               kPenumbraHigh: the reference anti-aliased the edge there, or a soft light's
//               penumbra), or whose reference is on the other side of 0.5 than one of its four
//               receiver neighbours;
//   edge band   receiver pixels within kEdgeBandRadius pixels (Euclidean) of an edge pixel;
//   edge error  mean |test - reference| over the edge band (0 when the band is empty).
//
//   Result<EdgeError> e = edge_error(esm_mask, exact_hard_reference, coverage);
//   // e->error, e->pixels
#include "metrics/mask_image.h"
#include "util/error.h"

namespace penumbra::metrics {

inline constexpr float kEdgeBandRadius = 3.0f;  // pixels

struct EdgeError {
  double error = 0.0;  // mean |test - ref| over the band
  size_t pixels = 0;   // band pixels
};

// The edge band of `reference` (1 = in the band), receivers only; sizes must match.
CoverageMask edge_band(const MaskImage& reference, const CoverageMask& coverage = {},
                       float radius = kEdgeBandRadius);

// Sizes must match (coverage, when not empty, must have width * height entries).
Result<EdgeError> edge_error(const MaskImage& test, const MaskImage& reference, const CoverageMask& coverage = {},
                             float radius = kEdgeBandRadius);

}  // namespace penumbra::metrics
