#pragma once
// The compare statistics and per-pass times as text a user can trust and keep: penumbra RMSE
// "n/a" when the comparison has no penumbra pixels, a progressive technique's convergence, and an export
// (JSON, or CSV by extension) for the UI's button and the scripts' `metrics` step.
//
//   if (Status s = write_metrics(controller, "metrics.json"); !s) report(s);
#include <string>

#include "sandbox/controller.h"
#include "metrics/mask_metrics.h"

namespace penumbra::sandbox {

// "0.0123", "0.0123 (unreliable: <why>)" (metrics::penumbra_reliability), or "n/a (no soft
// penumbra)" when the reference side has no soft-penumbra pixels.
std::string penumbra_rmse_text(const metrics::MaskErrors& e);

// How far the progressive techniques on screen (those whose pass reports progress, such as the
// reference) have got: "reference (raster: 412 / 1024 shadow maps (40%))"; "" when none does.
std::string progress_text(SandboxController& c);
// No technique on screen is still progressing.
bool progress_complete(SandboxController& c);

// {"frame", "size", "scene", "technique": {"name", "parameters", "progress"}, "viewer": {"resource", "min",
//  "max", "channel", "zoom", "center"}, "refused", "passes": [{"name", "type",
//  "last_ms", "median_ms"}], "compare": null | {"with": {...}, "view", "rmse", "rmse_penumbra"
//  (null without penumbra), "mae", "max_error", "pixels", "penumbra_pixels", "penumbra_reliable", "penumbra_unreliable_because",
//  "rmse_geometric_edge" (null without), "geometric_edge_pixels", "rmse_history": [...],
//  "passes": [...]}}. A technique's "progress": {"label", "unit", "done", "total", "complete"}, or
//  null when it reports none.
// The statistics are read back from the last rendered frame first.
std::string metrics_json(SandboxController& c);
// One row per pass and side ("side,pass,type,last_ms,median_ms"), then the compare statistics
// as "stat,<name>,<value>" rows.
std::string metrics_csv(SandboxController& c);
// .csv -> metrics_csv, anything else JSON; written whole (temporary file + rename).
Status write_metrics(SandboxController& c, const std::string& path);

}  // namespace penumbra::sandbox
