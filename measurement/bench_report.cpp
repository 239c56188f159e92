#include "measurement/bench_report.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace penumbra::measurement {

double BenchPass::gb_per_s() const { return ms > 0.0 ? static_cast<double>(traffic.total()) / (ms * 1e-3) / 1e9 : 0.0; }

std::vector<BenchPass> bench_passes(const std::vector<PassMedian>& medians, const graph::CompiledPlan& plan,
                                    const std::map<std::string, double>& tile_fractions) {
  std::vector<BenchPass> out;
  for (const PassMedian& m : medians) {
    BenchPass p{m.name, m.ms, {}, false};
    auto planned = std::find_if(plan.passes.begin(), plan.passes.end(),
                                [&](const graph::PlannedPass& q) { return q.name == m.name; });
    if (planned != plan.passes.end()) {
      p.traffic = planned->traffic;
      p.frame = planned->frame;
      if (auto f = tile_fractions.find(m.name); f != tile_fractions.end() && graph::dispatch_tile_list(*planned)) {
        p.tile_fraction = f->second;
        p.traffic = graph::pass_traffic(plan, *planned, f->second);
      }
    }
    out.push_back(std::move(p));
  }
  return out;
}

namespace {

// Share of the measured copy peak; 0 when no peak was measured.
double percent_of_peak(const BenchPass& p, const MemoryPeaks& peaks) {
  return peaks.measured && peaks.copy_gb_per_s > 0.0 ? 100.0 * p.gb_per_s() / peaks.copy_gb_per_s : 0.0;
}

nlohmann::ordered_json peaks_json(const MemoryPeaks& p) {
  if (!p.measured) return {{"measured", false}, {"problem", p.problem}};
  return {{"measured", true},
          {"copy_buffer_bytes", p.copy_buffer_bytes},
          {"copy_gb_per_s", p.copy_gb_per_s},
          {"fetch_texture", std::to_string(p.fetch_width) + "x" + std::to_string(p.fetch_height) + " RGBA8"},
          {"fetch_gtexels_per_s", p.fetch_gtexels_per_s},
          {"fetch_gb_per_s", p.fetch_gb_per_s}};
}

}  // namespace

void summarise_row(BenchRow& row) {
  row.total_ms = row.technique_ms = 0.0;
  row.penumbra_tiles.reset();
  for (const BenchPass& p : row.passes) {
    row.total_ms += p.ms;
    if (!p.frame) row.technique_ms += p.ms;
    // Every filter of a technique runs over the one list its classifier fills.
    if (p.tile_fraction) row.penumbra_tiles = std::max(row.penumbra_tiles.value_or(0.0), *p.tile_fraction);
  }
}

std::string bench_report_json(const BenchReport& report) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const BenchRow& r : report.rows) {
    nlohmann::ordered_json passes = nlohmann::ordered_json::array();
    for (const BenchPass& p : r.passes) {
      passes.push_back({{"name", p.name},
                        {"ms", p.ms},
                        {"read_bytes", p.traffic.read_bytes},
                        {"written_bytes", p.traffic.written_bytes},
                        {"gb_per_s", p.gb_per_s()},
                        {"percent_of_copy_peak", percent_of_peak(p, report.peaks)},
                        {"frame", p.frame}});
      if (p.tile_fraction) passes.back()["tile_fraction"] = *p.tile_fraction;
    }
    rows.push_back({{"technique", r.technique},
                    {"scene", r.scene},
                    {"size", std::to_string(r.width) + "x" + std::to_string(r.height)},
                    {"shadow_size", r.shadow_size},
                    {"passes", passes},
                    {"total_ms", r.total_ms},
                    {"technique_ms", r.technique_ms}});
    if (r.penumbra_tiles) rows.back()["penumbra_tile_fraction"] = *r.penumbra_tiles;
  }
  nlohmann::ordered_json j = {{"device", report.device},
                              {"renderer", report.renderer},
                              {"timing", report.timing},
                              {"peaks", peaks_json(report.peaks)},
                              {"rows", rows}};
  return j.dump(2) + "\n";
}

std::string bench_report_table(const BenchReport& report) {
  std::string out = "device: " + report.device + "\nrenderer: " + report.renderer + "\ntiming: " + report.timing +
                    "\nmeasured peaks: " + describe_memory_peaks(report.peaks) + "\n";
  char line[512];
  int width = 12;  // rows are labelled by technique and settings: as wide as the longest
  for (const BenchRow& r : report.rows) width = std::max(width, static_cast<int>(std::min<size_t>(r.technique.size(), 200)));
  std::snprintf(line, sizeof line, "%-*s %-11s %-10s %6s  %-24s %10s %9s %9s %7s\n", width, "technique", "scene", "size",
                "shadow", "pass", "median us", "MB moved", "GB/s", "% peak");
  out += line;
  for (const BenchRow& r : report.rows) {
    const std::string size = std::to_string(r.width) + "x" + std::to_string(r.height);
    bool first = true;
    for (const BenchPass& p : r.passes) {
      std::snprintf(line, sizeof line, "%-*s %-11s %-10s %6s  %-24s %10.1f %9.1f %9.1f %7.1f\n", width,
                    first ? r.technique.c_str() : "", first ? r.scene.c_str() : "", first ? size.c_str() : "",
                    first ? std::to_string(r.shadow_size).c_str() : "", p.name.c_str(), p.ms * 1e3,
                    static_cast<double>(p.traffic.total()) / 1e6, p.gb_per_s(), percent_of_peak(p, report.peaks));
      out += line;
      first = false;
    }
    std::snprintf(line, sizeof line, "%-*s %-11s %-10s %6s  %-24s %10.1f", width, "", "", "", "", "technique passes",
                  r.technique_ms * 1e3);
    out += line;
    if (r.penumbra_tiles) {
      std::snprintf(line, sizeof line, "   penumbra tiles %.1f%%", 100.0 * *r.penumbra_tiles);
      out += line;
    }
    std::snprintf(line, sizeof line, "\n%-*s %-11s %-10s %6s  %-24s %10.1f\n", width, "", "", "", "", "total", r.total_ms * 1e3);
    out += line;
  }
  return out;
}

}  // namespace penumbra::measurement
