#include "measurement/bench_report.h"

#include <algorithm>

#include <cstdio>

#include <nlohmann/json.hpp>

namespace penumbra::measurement {

std::string bench_report_json(const BenchReport& report) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const BenchRow& r : report.rows) {
    nlohmann::ordered_json passes = nlohmann::ordered_json::array();
    for (const PassMedian& p : r.passes) passes.push_back({{"name", p.name}, {"ms", p.ms}});
    rows.push_back({{"technique", r.technique},
                    {"scene", r.scene},
                    {"size", std::to_string(r.width) + "x" + std::to_string(r.height)},
                    {"shadow_size", r.shadow_size},
                    {"passes", passes},
                    {"total_ms", r.total_ms}});
  }
  nlohmann::ordered_json j = {{"device", report.device}, {"renderer", report.renderer}, {"rows", rows}};
  return j.dump(2) + "\n";
}

std::string bench_report_table(const BenchReport& report) {
  std::string out = "device: " + report.device + "\nrenderer: " + report.renderer + "\ntiming: " + report.timing + "\n";
  char line[512];
  int width = 12;  // rows are labelled by technique and settings: as wide as the longest
  for (const BenchRow& r : report.rows) width = std::max(width, static_cast<int>(std::min<size_t>(r.technique.size(), 200)));
  std::snprintf(line, sizeof line, "%-*s %-11s %-10s %6s  %-24s %10s\n", width, "technique", "scene", "size", "shadow",
                "pass", "median ms");
  out += line;
  for (const BenchRow& r : report.rows) {
    const std::string size = std::to_string(r.width) + "x" + std::to_string(r.height);
    bool first = true;
    for (const PassMedian& p : r.passes) {
      std::snprintf(line, sizeof line, "%-*s %-11s %-10s %6s  %-24s %10.3f\n", width, first ? r.technique.c_str() : "",
                    first ? r.scene.c_str() : "", first ? size.c_str() : "",
                    first ? std::to_string(r.shadow_size).c_str() : "", p.name.c_str(), p.ms);
      out += line;
      first = false;
    }
    std::snprintf(line, sizeof line, "%-*s %-11s %-10s %6s  %-24s %10.3f\n", width, "", "", "", "", "total", r.total_ms);
    out += line;
  }
  return out;
}

}  // namespace penumbra::measurement
