#pragma once
// The results of `penumbra bench` as a table and as the JSON of docs/evaluation.md:
//   {"device":..., "renderer":..., "peaks": {"copy_gb_per_s":..., ...},
//    "rows":[{"technique":..., "scene":..., "size":..., "shadow_size":...,
//             "passes":[{"name":..., "ms":..., "read_bytes":..., "written_bytes":...,
//                        "gb_per_s":..., "percent_of_copy_peak":..., "frame":...,
//                        "tile_fraction":... (passes over a tile list only)}],
//             "total_ms":..., "technique_ms":...,
//             "penumbra_tile_fraction":... (techniques whose filters run over tile lists only)}]}
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "graph/plan.h"
#include "measurement/eval_capture.h"
#include "measurement/memory_peaks.h"

namespace penumbra::measurement {

struct BenchPass {
  std::string name;
  double ms = 0.0;                   // median
  graph::PassTraffic traffic;        // bytes per execution, from the plan (graph --traffic)
  bool frame = false;                // G-buffer, lighting: the frame's passes, not the technique's
  std::optional<double> tile_fraction;  // a pass over a tile list: the share of tiles it ran over
  double gb_per_s() const;           // traffic / time; 0 when the time is 0
};

struct BenchRow {
  std::string technique, scene;
  int width = 0, height = 0, shadow_size = 0;
  std::vector<BenchPass> passes;  // execution order
  double total_ms = 0.0;          // sum of the pass medians
  double technique_ms = 0.0;      // sum over the technique's own passes
  // The share of the screen's tiles the technique's filters ran over (the classifier's penumbra
  // tiles, passes/shadow_tiles); unset for a technique that runs over every pixel.
  std::optional<double> penumbra_tiles;
};

// Sums the row's times and takes its tile share from its passes.
void summarise_row(BenchRow& row);

// The medians of a session's passes, each with its planned traffic; a pass over a tile list
// with the traffic of the tiles it ran over (`tile_fractions`: pass name -> share read back).
std::vector<BenchPass> bench_passes(const std::vector<PassMedian>& medians, const graph::CompiledPlan& plan,
                                    const std::map<std::string, double>& tile_fractions = {});

struct BenchReport {
  std::string device;    // GL context backend, e.g. "egl (device 0: NVIDIA)"
  std::string renderer;  // GL_RENDERER
  std::string timing;    // how passes were timed
  MemoryPeaks peaks;     // measured once per run
  std::vector<BenchRow> rows;
};

std::string bench_report_json(const BenchReport& report);
std::string bench_report_table(const BenchReport& report);

}  // namespace penumbra::measurement
