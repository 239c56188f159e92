// Compile time of synthetic graphs of 10, 100 and 1,000 passes (target: 1,000 in < 1 ms).
// The graph is a realistic mix: per "technique block" a shadow map, a camera depth, a filter,
// a ping-pong blur and an in-place blur, with a culled debug pass; everything is an output
// so nothing but the debug passes is culled. Run from a Release build:
//   build/graph-rel/tests/benchmarks/penumbra_graph_bench --benchmark_repetitions=10
#include <benchmark/benchmark.h>

#include "graph/builder.h"
#include "graph/compiler.h"
#include "support/generic_pass_types.h"

namespace {

using namespace penumbra::graph;

GraphDesc synthetic_graph(int passes) {
  GraphBuilder b("synthetic");
  auto scene = b.import("scene"), light = b.import("light"), camera = b.import("camera");
  int made = 0;
  for (int block = 0; made < passes; ++block) {
    std::string k = std::to_string(block);
    auto sm = b.texture("sm" + k, Format::DEPTH32F, SizeExpr::shadow());
    auto depth = b.texture("depth" + k, Format::DEPTH32F, SizeExpr::screen());
    auto mask = b.texture("mask" + k, Format::R16F, SizeExpr::screen());
    auto debug = b.texture("debug" + k, Format::R16F, SizeExpr::screen());
    b.pass("shadow_map", "light" + k).read("scene", scene).read("light", light).write("depth", sm);
    b.pass("depth_prepass", "camera" + k).read("scene", scene).read("camera", camera).write("depth", depth);
    b.pass("penumbra_filter", "filter" + k).read("shadow_map", sm).read("depth", depth).write("mask", mask)
        .param("samples", 16);
    b.pass("blur", "debug" + k).read("input", mask).write("output", debug);
    b.pass("blur", "blur" + k).read("input", mask).write("output", mask).param("radius", 3);
    b.pass("blur_in_place", "smooth" + k).read_write("image", mask);
    made += 6;
    b.output(mask);
  }
  return b.build();
}

void BM_GraphCompile(benchmark::State& state) {
  PassTypeRegistry registry;
  register_generic_pass_types(registry);
  GraphDesc graph = synthetic_graph(static_cast<int>(state.range(0)));
  ParameterSet params(graph.parameters);
  for (auto _ : state) {
    auto plan = compile(graph, registry, params, {1920, 1080, 2048});
    if (!plan) state.SkipWithError("compile failed");
    benchmark::DoNotOptimize(plan);
  }
  state.counters["passes"] = static_cast<double>(graph.passes.size());
}
BENCHMARK(BM_GraphCompile)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
