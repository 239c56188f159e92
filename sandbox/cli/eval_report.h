#pragma once
// The results of `penumbra eval` as a table and as the JSON of docs/evaluation.md:
//   {"scene":..., "reference":..., "rows":[{"technique":..., "rmse":..., "rmse_penumbra":...,
//    "mae":..., "max_error":..., "ssim":..., "edge_error":..., "gpu_ms":...}]}
#include <string>
#include <vector>

#include "metrics/mask_metrics.h"

namespace penumbra::cli {

struct EvalRow {
  std::string technique;
  metrics::MaskErrors errors;
  double gpu_ms = 0.0;  // median over the measured frames of the technique's own passes
};

struct EvalReport {
  std::string scene;
  std::string reference;  // "raytraced" or "raster"
  std::vector<EvalRow> rows;
};

std::string eval_report_json(const EvalReport& report);
std::string eval_report_table(const EvalReport& report);

}  // namespace penumbra::cli
