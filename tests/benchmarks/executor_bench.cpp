// Per-frame CPU overhead of the executor for a 20-pass graph (target: < 50 us per frame).
// The passes bind their slots and return without GPU work, so what is measured is the
// executor's own work: barriers, context setup, parameter lookup, state resets, debug groups.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>

#include "exec/executor.h"
#include "gl/context.h"
#include "graph/builder.h"
#include "graph/compiler.h"

using namespace penumbra;

namespace {

class TouchPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    benchmark::DoNotOptimize(ctx.texture("out").id());
    if (ctx.bound("in")) benchmark::DoNotOptimize(ctx.texture("in").id());
    benchmark::DoNotOptimize(ctx.real("amount"));
    return {};
  }
};

gl::Context& context() {
  static std::unique_ptr<gl::Context> ctx = [] {
    auto c = gl::create_context({.kind = gl::ContextKind::osmesa, .width = 16, .height = 16, .debug_output = false});
    if (!c) {
      std::fprintf(stderr, "%s\n", c.error().to_string().c_str());
      std::exit(1);
    }
    return std::move(*c);
  }();
  return *ctx;
}

void BM_ExecutorFrame20Passes(benchmark::State& state) {
  context();
  using namespace graph;
  exec::PassLibrary library;
  PassTypeDecl decl{.name = "touch"};
  decl.slots = {{"in", Access::read, SlotKind::texture, {}, Usage::sampled, false},
                {"out", Access::write, SlotKind::texture, {}, Usage::image_store, true}};
  ParamDesc amount{.name = "amount", .type = ParamType::real, .default_value = 1.0, .min = 0.0, .max = 10.0};
  decl.params = {amount};
  library.add({decl, [] { return std::make_unique<TouchPass>(); }});

  GraphBuilder b("overhead");
  ParamDesc live{.name = "live", .type = ParamType::real, .default_value = 1.0, .min = 0.0, .max = 10.0};
  b.parameter(live);
  TextureHandle prev = b.texture("t0", Format::R16F, SizeExpr::screen());
  b.pass("touch", "p0").write("out", prev).param("amount", "$live");
  for (int i = 1; i < 20; ++i) {
    TextureHandle next = b.texture("t" + std::to_string(i), Format::R16F, SizeExpr::screen());
    b.pass("touch", "p" + std::to_string(i)).read("in", prev).write("out", next).param("amount", "$live");
    prev = next;
  }
  b.output(prev);
  GraphDesc g = b.build();
  ParameterSet params(g.parameters);
  auto plan = compile(g, library.declarations(), params, {256, 256, 256});
  if (!plan) {
    state.SkipWithError("compile failed");
    return;
  }
  exec::ShaderCache shaders;
  exec::TexturePool pool;
  exec::Executor executor(library, shaders, pool);
  executor.options().timing_enabled = state.range(0) != 0;
  if (!executor.set_plan(std::move(*plan))) {
    state.SkipWithError("set_plan failed");
    return;
  }
  exec::FrameInputs frame;
  if (Status s = executor.execute(params, frame); !s) {
    state.SkipWithError(s.error().to_string().c_str());
    return;
  }
  for (auto _ : state) {
    Status s = executor.execute(params, frame);
    benchmark::DoNotOptimize(s.ok());
  }
  state.SetLabel(state.range(0) ? "timing on (glFinish per pass on llvmpipe)" : "timing off");
}

}  // namespace

BENCHMARK(BM_ExecutorFrame20Passes)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
