#include "measurement/eval_report.h"

#include <algorithm>

#include <cstdio>

#include <nlohmann/json.hpp>

namespace penumbra::measurement {

std::string eval_report_json(const EvalReport& report) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  const bool flicker = !report.flicker_motion.empty();
  for (const EvalRow& r : report.rows) {
    nlohmann::ordered_json row = {{"technique", r.technique},
                                  {"rmse", r.errors.rmse},
                                  {"rmse_penumbra", r.errors.rmse_penumbra},
                                  {"mae", r.errors.mae},
                                  {"max_error", r.errors.max_error},
                                  {"ssim", r.errors.ssim},
                                  {"edge_error", r.errors.edge_error},
                                  {"gpu_ms", r.gpu_ms}};
    if (flicker) {
      row["temporal_change"] = r.temporal_change;
      row["flicker"] = r.flicker;
    }
    rows.push_back(std::move(row));
  }
  nlohmann::ordered_json j = {{"scene", report.scene}, {"reference", report.reference}};
  if (flicker) {
    j["flicker_motion"] = report.flicker_motion;
    j["flicker_frames"] = report.flicker_frames;
    j["flicker_reference"] = report.flicker_reference;
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
  std::snprintf(line, sizeof line, "%-*s %9s %13s %9s %9s %7s %9s %10s%s\n", width, "technique", "RMSE", "RMSE penumbra",
                "MAE", "max", "SSIM", "edge", "ms", flicker ? "   flicker" : "");
  out += line;
  for (const EvalRow& r : report.rows) {
    std::snprintf(line, sizeof line, "%-*s %9.5f %13.5f %9.5f %9.4f %7.4f %9.5f %10.3f", width, r.technique.c_str(),
                  r.errors.rmse, r.errors.rmse_penumbra, r.errors.mae, r.errors.max_error, r.errors.ssim,
                  r.errors.edge_error, r.gpu_ms);
    out += line;
    if (flicker) {
      std::snprintf(line, sizeof line, " %+10.5f", r.flicker);
      out += line;
    }
    out += "\n";
  }
  return out;
}

}  // namespace penumbra::measurement
