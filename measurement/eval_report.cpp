#include "measurement/eval_report.h"

#include <algorithm>

#include <cstdio>

#include <nlohmann/json.hpp>

namespace penumbra::measurement {

std::string eval_report_json(const EvalReport& report) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  const bool flicker = !report.flicker_motion.empty();
  for (const EvalRow& r : report.rows) {
    const metrics::MaskErrors& e = r.errors;
    nlohmann::ordered_json row = {{"technique", r.technique},
                                  {"rmse", e.rmse},
                                  // Not applicable without a soft penumbra (a point light, size 0).
                                  {"rmse_penumbra", e.penumbra_pixels ? nlohmann::ordered_json(e.rmse_penumbra) : nullptr},
                                  {"penumbra_pixels", e.penumbra_pixels},
                                  {"penumbra_reliable", e.reliability.reliable},
                                  {"penumbra_unreliable_because", e.reliability.reason},
                                  {"rmse_geometric_edge", e.geometric_edge_pixels ? nlohmann::ordered_json(e.rmse_geometric_edge) : nullptr},
                                  {"geometric_edge_pixels", e.geometric_edge_pixels},
                                  {"mae", r.errors.mae},
                                  {"max_error", r.errors.max_error},
                                  {"ssim", r.errors.ssim},
                                  {"edge_error", r.errors.edge_error},
                                  {"gpu_ms", r.gpu_ms}};
    if (flicker) {
      row["temporal_change"] = r.temporal_change;
      row["flicker"] = r.flicker;
      row["temporal_error"] = r.temporal_error;
      row["temporal_pixels"] = r.temporal_pixels;
    }
    rows.push_back(std::move(row));
  }
  nlohmann::ordered_json j = {{"scene", report.scene}, {"reference", report.reference}};
  if (flicker) {
    j["flicker_motion"] = report.flicker_motion;
    j["flicker_frames"] = report.flicker_frames;
    j["flicker_step_degrees"] = report.flicker_degrees_per_frame;
    j["flicker_match"] = report.flicker_match;
    j["flicker_reference"] = report.flicker_reference;
    j["flicker_pixels"] = report.flicker_pixels;
  }
  j["rows"] = rows;
  return j.dump(2) + "\n";
}

std::string eval_report_table(const EvalReport& report) {
  std::string out;
  char line[512];
  // Rows are labelled by technique and settings ("pmchss:variant=regular"): as wide as the longest.
  int width = 14;
  for (const EvalRow& r : report.rows) width = std::max(width, static_cast<int>(std::min<size_t>(r.technique.size(), 200)));
  const bool flicker = !report.flicker_motion.empty();
  std::snprintf(line, sizeof line, "%-*s %9s %13s %8s %13s %9s %9s %7s %9s %10s%s\n", width, "technique", "RMSE",
                "RMSE penumbra", "pixels", "RMSE geo-edge", "MAE", "max", "SSIM", "edge", "ms", flicker ? "    flicker  t-error" : "");
  out += line;
  std::string unreliable;
  for (const EvalRow& r : report.rows) {
    const metrics::MaskErrors& e = r.errors;
    char penumbra[32], geo[32];
    if (e.penumbra_pixels)
      std::snprintf(penumbra, sizeof penumbra, "%s%.5f", e.reliability.reliable ? "" : "*", e.rmse_penumbra);
    else
      std::snprintf(penumbra, sizeof penumbra, "n/a");
    if (e.geometric_edge_pixels)
      std::snprintf(geo, sizeof geo, "%.5f", e.rmse_geometric_edge);
    else
      std::snprintf(geo, sizeof geo, "n/a");
    std::snprintf(line, sizeof line, "%-*s %9.5f %13s %8zu %13s %9.5f %9.4f %7.4f %9.5f %10.3f", width, r.technique.c_str(),
                  e.rmse, penumbra, e.penumbra_pixels, geo, e.mae, e.max_error, e.ssim, e.edge_error, r.gpu_ms);
    out += line;
    if (flicker) {
      std::snprintf(line, sizeof line, " %+10.5f %8.5f", r.flicker, r.temporal_error);
      out += line;
    }
    out += "\n";
    if (!e.reliability.reliable && unreliable.empty()) unreliable = e.reliability.reason;
  }
  // The classes are the frame's, the same for every row: one note.
  if (!unreliable.empty())
    out += "* penumbra RMSE unreliable on this frame: " + unreliable + " (docs/evaluation.md, \"Pixel classes\")\n";
  return out;
}

}  // namespace penumbra::measurement
