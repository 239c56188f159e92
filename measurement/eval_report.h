#pragma once
// The results of `penumbra eval` as a table and as the JSON of docs/evaluation.md:
//   {"scene":..., "reference":..., "rows":[{"technique":..., "rmse":..., "rmse_penumbra": ... | null,
//    "penumbra_pixels":..., "penumbra_reliable":..., "penumbra_unreliable_because": "...",
//    "rmse_geometric_edge": ... | null, "geometric_edge_pixels":..., "mae":..., "max_error":...,
//    "ssim":..., "edge_error":..., "gpu_ms":...}]}
// The pixel classes behind the penumbra and geometric-edge columns: metrics/pixel_classes.h.
// With --flicker, the top level adds "flicker_motion", "flicker_frames", "flicker_step_degrees",
// "flicker_match" (pixels; 0: bilinear reprojection), "flicker_reference" (the reference's own
// temporal change) and "flicker_pixels" (the pixel pairs it compared), and each row
// "temporal_change", "flicker" (its temporal change minus the reference's), "temporal_error"
// (metrics::temporal_error) and "temporal_pixels" (the pixel pairs that compared).
#include <string>
#include <vector>

#include "metrics/mask_metrics.h"

namespace penumbra::measurement {

struct EvalRow {
  std::string technique;
  metrics::MaskErrors errors;
  double gpu_ms = 0.0;  // median over the measured frames of the technique's own passes
  double temporal_change = 0.0;  // --flicker: mean |change| between reprojected frames
  double flicker = 0.0;          // temporal_change minus the reference's on the same frames
  double temporal_error = 0.0;   // mean |its change - the reference's change| per pixel
  size_t temporal_pixels = 0;    // pixel pairs temporal_error compared
};

struct EvalReport {
  std::string scene;
  std::string reference;  // "raytraced" or "raster"
  std::vector<EvalRow> rows;
  std::string flicker_motion;      // "pan" or "light"; empty: no flicker measured
  int flicker_frames = 0;
  float flicker_degrees_per_frame = 0.0f;  // the motion's step (a pan given in pixels: resolved)
  float flicker_match = 0.0f;      // metrics::Reprojection::match_within
  double flicker_reference = 0.0;  // the reference's temporal change
  size_t flicker_pixels = 0;       // pixel pairs the reference's change compared
};

std::string eval_report_json(const EvalReport& report);
std::string eval_report_table(const EvalReport& report);

}  // namespace penumbra::measurement
