#pragma once
// Quality of a technique's shadow_mask against a reference mask of the same frame, over receiver
// pixels only (coverage mask; background is excluded from every statistic, and so are receivers
// the light does not reach: pixel_classes.h).
//
//   Result<MaskErrors> e = compare_masks(technique_mask, reference_mask, gbuffer_coverage, classes);
//   if (e) table.add(e->rmse, e->rmse_penumbra, e->max_error, e->ssim);
#include "metrics/mask_image.h"
#include "metrics/pixel_classes.h"
#include "util/error.h"

namespace penumbra::metrics {

struct MaskErrors {
  double rmse = 0.0;           // sqrt(mean((test - ref)^2)) over receiver pixels
  double mae = 0.0;            // mean(|test - ref|)
  // RMSE over the soft penumbra (pixel_classes.h); meaningless when penumbra_pixels == 0 (0 then;
  // reports write null).
  double rmse_penumbra = 0.0;
  double max_error = 0.0;      // max |test - ref|
  double ssim = 1.0;           // masked Gaussian-window SSIM, see masked_ssim()
  double edge_error = 0.0;     // mean |test - ref| within 3 px of a reference edge (metrics/edge_error.h)
  size_t pixels = 0;           // receiver pixels compared
  size_t penumbra_pixels = 0;  // soft penumbra
  size_t edge_pixels = 0;      // pixels of the edge band
  double rmse_geometric_edge = 0.0;  // RMSE over the geometric-edge class (0 when none)
  size_t geometric_edge_pixels = 0;
  PenumbraReliability reliability;   // whether rmse_penumbra can carry a verdict
};

// Sizes must match (and coverage, when not empty, must have width * height entries). The classes
// come from the reference alone: no geometric edges (the G-buffer is not known here).
Result<MaskErrors> compare_masks(const MaskImage& test, const MaskImage& reference,
                                 const CoverageMask& coverage = {});
// With the classes of the frame (classify_pixels() with the G-buffer), of the same size.
Result<MaskErrors> compare_masks(const MaskImage& test, const MaskImage& reference, const CoverageMask& coverage,
                                 const PixelClasses& classes);

// SSIM (Wang et al. 2004) with the standard 11x11 Gaussian window (sigma 1.5 px), C1 = (0.01)^2,
// C2 = (0.03)^2 for values in [0, 1]. Masked: window statistics are weighted by coverage (background
// pixels get weight 0 and the weights are renormalised) and the SSIM map is averaged over receiver
// pixels. Identical images give exactly 1.
Result<double> masked_ssim(const MaskImage& a, const MaskImage& b, const CoverageMask& coverage = {});

}  // namespace penumbra::metrics
