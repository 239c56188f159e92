#pragma once
// The compare statistics and per-pass times as text a user can trust and keep: penumbra RMSE
// "n/a" when the comparison has no penumbra pixels, the reference's convergence, and an export
// (JSON, or CSV by extension) for the UI's button and the scripts' `metrics` step.
//
//   if (Status s = write_metrics(controller, "metrics.json"); !s) report(s);
#include <string>

#include "app/controller.h"
#include "metrics/mask_metrics.h"

namespace penumbra::sandbox {

// "0.0123", or "n/a (no penumbra)" when the reference side has no penumbra pixels.
std::string penumbra_rmse_text(const metrics::MaskErrors& e);

// How far the reference technique (when one side is `reference`) has got: "raster 412/1024
// shadow maps", "raytraced converged (921600 rays)"; "" when neither side is the reference.
std::string reference_progress_text(SandboxController& c);
bool reference_converged(SandboxController& c);

// {"frame", "size", "scene", "technique": {"name", "parameters"}, "viewer": {"resource", "min",
//  "max", "channel", "zoom", "center"}, "refused", "passes": [{"name", "type",
//  "last_ms", "median_ms"}], "compare": null | {"with": {...}, "view", "rmse", "rmse_penumbra"
//  (null without penumbra), "mae", "max_error", "pixels", "penumbra_pixels", "reference":
//  {"method", "done", "total", "converged"} | null, "rmse_history": [...], "passes": [...]}}.
// The statistics are read back from the last rendered frame first.
std::string metrics_json(SandboxController& c);
// One row per pass and side ("side,pass,type,last_ms,median_ms"), then the compare statistics
// as "stat,<name>,<value>" rows.
std::string metrics_csv(SandboxController& c);
// .csv -> metrics_csv, anything else JSON; written whole (temporary file + rename).
Status write_metrics(SandboxController& c, const std::string& path);

}  // namespace penumbra::sandbox
