// The executor on OSMesa: a multi-pass graph of raster and compute passes with numeric
// read-back, reuse on/off equivalence, culling, per-frame parameters, repeat, timing, the
// texture pool across recompiles and resizes, keep-alive.
#include <gtest/gtest.h>

#include "exec/executor.h"
#include "graph/builder.h"
#include "graph/compiler.h"
#include "test_support/gl_context.h"
#include "test_passes.h"

using namespace penumbra;
using namespace penumbra::graph;

namespace {

constexpr int kW = 16, kH = 8;

GraphDesc test_graph() {
  GraphBuilder b("executor_test");
  ParamDesc offset{.name = "offset", .type = ParamType::real, .default_value = 0.5, .min = -10.0, .max = 10.0};
  offset.description = "added by add1 (uniform)";
  ParamDesc passes{.name = "scale_passes", .type = ParamType::integer, .default_value = 3, .min = 1, .max = 8};
  passes.description = "repeat count of the scale pass";
  passes.structural = true;
  ParamDesc extra{.name = "use_extra", .type = ParamType::boolean, .default_value = false};
  extra.description = "run the extra ping-pong add";
  extra.structural = true;
  b.parameter(offset);
  b.parameter(passes);
  b.parameter(extra);
  SizeExpr size = SizeExpr::fixed(kW, kH);
  TextureHandle a = b.texture("a", Format::R32F, size);
  TextureHandle bt = b.texture("b", Format::R32F, size);
  TextureHandle c = b.texture("c", Format::R32F, size);
  TextureHandle unused = b.texture("unused", Format::R32F, size);
  b.pass("fill", "fill").write("out", a).param("value", 1.0);
  b.pass("add", "add1").read("in", a).write("out", bt).param("amount", "$offset");
  b.pass("add", "add2").read("in", bt).write("out", c).param("amount", 0.25);
  b.pass("scale", "scale").read_write("img", c).param("factor", 2.0).repeat("$scale_passes");
  b.pass("add", "dead").read("in", a).write("out", unused).param("amount", 9.0);
  b.pass("add", "extra").read("in", c).write("out", c).param("amount", 100.0).enabled("$use_extra");
  b.output(c);
  return b.build();
}

float expected(int x, float offset, int scale_passes, bool extra) {
  float v = 1.0f + 0.001f * static_cast<float>(x);
  v = v + offset;
  v = v + 0.25f;
  for (int i = 0; i < scale_passes; ++i) v *= 2.0f;
  if (extra) v += 100.0f;
  return v;
}

class Executor : public ::testing::Test {
 protected:
  void SetUp() override {
    test::gl_context();
    test::register_test_passes(library_);
    test::execution_counts().clear();
  }
  CompiledPlan compile_plan(const ParameterSet& params, CompileOptions options = {}) {
    auto plan = compile(graph_, library_.declarations(), params, {64, 64, 64}, options);
    EXPECT_TRUE(plan) << (plan ? "" : plan.errors().front().to_string());
    return std::move(*plan);
  }
  std::vector<float> run(exec::Executor& ex, const ParameterSet& params, const std::string& resource = "c") {
    exec::FrameInputs frame;
    Status s = ex.execute(params, frame);
    EXPECT_TRUE(s) << (s ? "" : s.error().to_string());
    gl::Texture* t = ex.resource(resource);
    EXPECT_NE(t, nullptr);
    return t ? t->read() : std::vector<float>{};
  }
  GraphDesc graph_ = test_graph();
  exec::PassLibrary library_;
  exec::ShaderCache shaders_;
  exec::TexturePool pool_;
};

TEST_F(Executor, MultiPassGraphOfRasterAndComputePassesComputesExactValues) {
  ParameterSet params(graph_.parameters);
  exec::Executor ex(library_, shaders_, pool_);
  ASSERT_TRUE(ex.set_plan(compile_plan(params)));
  std::vector<float> c = run(ex, params);
  ASSERT_EQ(c.size(), size_t(kW * kH));
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) ASSERT_FLOAT_EQ(c[y * kW + x], expected(x, 0.5f, 3, false)) << x << "," << y;
}

TEST_F(Executor, ReuseOnAndOffGiveIdenticalPixels) {
  ParameterSet params(graph_.parameters);
  ASSERT_TRUE(params.set("use_extra", true));
  exec::Executor reuse(library_, shaders_, pool_);
  exec::TexturePool other_pool;
  exec::Executor no_reuse(library_, shaders_, other_pool);
  CompiledPlan with = compile_plan(params);
  CompiledPlan without = compile_plan(params, {.no_reuse = true});
  EXPECT_LT(with.physical.size(), without.physical.size());
  EXPECT_LT(with.memory.assigned_bytes, without.memory.assigned_bytes);
  ASSERT_TRUE(reuse.set_plan(std::move(with)));
  ASSERT_TRUE(no_reuse.set_plan(std::move(without)));
  std::vector<float> a = run(reuse, params), b = run(no_reuse, params);
  EXPECT_EQ(a, b);
  EXPECT_FLOAT_EQ(a[3], expected(3, 0.5f, 3, true));
}

TEST_F(Executor, CulledPassNeverRuns) {
  ParameterSet params(graph_.parameters);
  exec::Executor ex(library_, shaders_, pool_);
  CompiledPlan plan = compile_plan(params);
  EXPECT_NE(std::find(plan.culled.begin(), plan.culled.end(), "dead"), plan.culled.end());
  ASSERT_TRUE(ex.set_plan(std::move(plan)));
  run(ex, params);
  run(ex, params);
  EXPECT_EQ(test::execution_counts()["fill"], 2);
  EXPECT_EQ(test::execution_counts().count("dead"), 0u);
  EXPECT_EQ(test::execution_counts().count("extra"), 0u);  // disabled
}

TEST_F(Executor, UniformParameterChangesApplyNextFrameWithoutRecompiling) {
  ParameterSet params(graph_.parameters);
  exec::Executor ex(library_, shaders_, pool_);
  ASSERT_TRUE(ex.set_plan(compile_plan(params)));
  EXPECT_FLOAT_EQ(run(ex, params)[0], expected(0, 0.5f, 3, false));
  ASSERT_TRUE(params.set("offset", 2.0));
  EXPECT_FLOAT_EQ(run(ex, params)[0], expected(0, 2.0f, 3, false));
}

TEST_F(Executor, RepeatChainsThroughVersions) {
  for (int n : {1, 2, 5}) {
    ParameterSet params(graph_.parameters);
    ASSERT_TRUE(params.set("scale_passes", n));
    exec::Executor ex(library_, shaders_, pool_);
    ASSERT_TRUE(ex.set_plan(compile_plan(params)));
    EXPECT_FLOAT_EQ(run(ex, params)[5], expected(5, 0.5f, n, false)) << n;
    // A single repetition keeps the declared name; more are named name[i].
    std::string last = n == 1 ? "scale" : "scale[" + std::to_string(n - 1) + "]";
    EXPECT_EQ(test::execution_counts()[last], 1) << n;
  }
}

TEST_F(Executor, EveryPassIsTimedOncePerFrame) {
  ParameterSet params(graph_.parameters);
  exec::Executor ex(library_, shaders_, pool_);
  ASSERT_TRUE(ex.set_plan(compile_plan(params)));
  for (int i = 0; i < 3; ++i) run(ex, params);
  ASSERT_EQ(ex.timings().size(), ex.plan().passes.size());
  // llvmpipe: timer queries do not measure the work, so the executor uses glFinish + clock.
  EXPECT_EQ(ex.timing_mode(), exec::TimingMode::cpu_finish);
  for (const exec::PassTiming& t : ex.timings()) {
    EXPECT_EQ(t.history.size(), 3u) << t.name;
    EXPECT_GE(t.last_ms, 0.0) << t.name;
  }
}

// A recompile keeps the mode the frames use: a label drawn before the next frame (the sandbox's
// "times:") said "off" / "glFinish" on a GPU.
TEST_F(Executor, ANewPlanKeepsTheTimingModeOfTheFrames) {
  ParameterSet params(graph_.parameters);
  exec::Executor ex(library_, shaders_, pool_);
  ex.options().force_timing_mode = exec::TimingMode::gpu_timestamps;
  ASSERT_TRUE(ex.set_plan(compile_plan(params)));
  run(ex, params);
  ASSERT_EQ(ex.timing_mode(), exec::TimingMode::gpu_timestamps);
  ASSERT_TRUE(ex.set_plan(compile_plan(params)));
  EXPECT_EQ(ex.timing_mode(), exec::TimingMode::gpu_timestamps);
  EXPECT_STREQ(exec::timing_mode_name(ex.timing_mode()), "GPU timestamps");
  run(ex, params);
  ex.flush_timings();
  for (const exec::PassTiming& t : ex.timings()) EXPECT_EQ(t.history.size(), 1u) << t.name;
}

TEST_F(Executor, GpuTimestampsAreQueuedAndEveryFrameIsRecordedAfterFlush) {
  ParameterSet params(graph_.parameters);
  exec::Executor ex(library_, shaders_, pool_);
  ex.options().force_timing_mode = exec::TimingMode::gpu_timestamps;
  ASSERT_TRUE(ex.set_plan(compile_plan(params)));
  constexpr int kFrames = 20;  // more than the pending-frame cap, so the queue must drain
  for (int i = 0; i < kFrames; ++i) run(ex, params);
  ex.flush_timings();
  EXPECT_EQ(ex.timing_mode(), exec::TimingMode::gpu_timestamps);
  for (const exec::PassTiming& t : ex.timings()) {
    EXPECT_EQ(t.history.size(), size_t(kFrames)) << t.name;
    for (float ms : t.history) EXPECT_GE(ms, 0.0f) << t.name;
  }
}

TEST_F(Executor, KeepAliveResourceIsNotOverwrittenByReuse) {
  ParameterSet params(graph_.parameters);
  exec::Executor ex(library_, shaders_, pool_);
  ASSERT_TRUE(ex.set_plan(compile_plan(params, {.keep_alive = {"a", "b"}})));
  std::vector<float> a = run(ex, params, "a");
  std::vector<float> b = run(ex, params, "b");
  for (int x = 0; x < kW; ++x) {
    EXPECT_FLOAT_EQ(a[x], 1.0f + 0.001f * x);
    EXPECT_FLOAT_EQ(b[x], 1.0f + 0.001f * x + 0.5f);
  }
}

TEST_F(Executor, ImmediateModeRunsTheSameFrame) {
  ParameterSet params(graph_.parameters);
  exec::Executor ex(library_, shaders_, pool_);
  ex.options().immediate = true;
  ASSERT_TRUE(ex.set_plan(compile_plan(params)));
  EXPECT_FLOAT_EQ(run(ex, params)[7], expected(7, 0.5f, 3, false));
}

TEST_F(Executor, MissingPassImplementationIsAnErrorAndKeepsThePreviousPlan) {
  ParameterSet params(graph_.parameters);
  exec::Executor ex(library_, shaders_, pool_);
  ASSERT_TRUE(ex.set_plan(compile_plan(params)));
  CompiledPlan bogus = compile_plan(params);
  bogus.passes[0].type = "no_such_type";
  Status s = ex.set_plan(std::move(bogus));
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("no_such_type"), std::string::npos);
  EXPECT_FLOAT_EQ(run(ex, params)[0], expected(0, 0.5f, 3, false));
}

TEST_F(Executor, TexturePoolReusesTexturesAcrossRecompilesAndStaysBoundedAcrossResizes) {
  ParameterSet params(graph_.parameters);
  exec::Executor ex(library_, shaders_, pool_);
  ASSERT_TRUE(ex.set_plan(compile_plan(params)));
  size_t first = pool_.texture_count();
  gl::Texture* before = ex.resource("c");
  ASSERT_TRUE(ex.set_plan(compile_plan(params)));
  EXPECT_EQ(pool_.texture_count(), first);  // same descriptors: taken back from the pool
  EXPECT_EQ(ex.resource("c"), before);
  // Many different sizes: stale textures are freed after kKeepGenerations plan builds.
  for (int i = 1; i <= 20; ++i) {
    GraphDesc g = graph_;
    for (ResourceDecl& r : g.resources) r.size = SizeExpr::fixed(kW + i, kH);
    auto plan = compile(g, library_.declarations(), params, {64, 64, 64});
    ASSERT_TRUE(plan);
    ASSERT_TRUE(ex.set_plan(std::move(*plan)));
    EXPECT_LE(pool_.texture_count(), first * (exec::TexturePool::kKeepGenerations + 1)) << i;
  }
  // Once the sizes stop changing, frames of the last plan free what it does not use.
  for (int f = 0; f < exec::TexturePool::kKeepFrames; ++f) run(ex, params);
  EXPECT_EQ(pool_.texture_count(), first);
}

}  // namespace
