#pragma once
// The results of `penumbra bench` as a table and as the JSON of docs/evaluation.md:
//   {"device":..., "renderer":..., "rows":[{"technique":..., "scene":..., "size":...,
//    "shadow_size":..., "passes":[{"name":..., "ms":...}], "total_ms":...}]}
#include <string>
#include <vector>

#include "measurement/eval_capture.h"

namespace penumbra::measurement {

struct BenchRow {
  std::string technique, scene;
  int width = 0, height = 0, shadow_size = 0;
  std::vector<PassMedian> passes;  // median ms per pass, execution order
  double total_ms = 0.0;           // sum of the pass medians
};

struct BenchReport {
  std::string device;    // GL context backend, e.g. "egl (device 0: NVIDIA)"
  std::string renderer;  // GL_RENDERER
  std::string timing;    // how passes were timed
  std::vector<BenchRow> rows;
};

std::string bench_report_json(const BenchReport& report);
std::string bench_report_table(const BenchReport& report);

}  // namespace penumbra::measurement
