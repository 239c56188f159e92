// The shared separable_filter pass on known texels (an upload pass before it): every mode's
// values against the formula, every channel of a four-channel format, 16-bit UNORM and SNORM
// textures (the output's image qualifier follows the texture), the bilateral mode stopping at a
// depth edge, a gaussian sized by the frame's light (penumbra_height) for directional and spot
// lights, and a bilateral filter without its depth slot refused with the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <vector>

#include "exec/executor.h"
#include "graph/builder.h"
#include "graph/compiler.h"
#include "passes/shared_passes.h"
#include "test_support/gl_context.h"
#include "test_support/read_back.h"
#include "test_support/upload_pass.h"

using namespace penumbra;
using graph::Format;

namespace {

constexpr int kW = 9, kH = 3;

struct FilterRun {
  Status status;
  test::TextureImage out;
};

// One x-axis pass of separable_filter over `input` (and `depth` when given), read back.
// The texture is input's size; `frame` carries the light (penumbra_height).
FilterRun filter_x(Format format, const test::TextureImage& input, const std::map<std::string, graph::ParamValue>& params,
             const test::TextureImage* depth = nullptr, const exec::FrameInputs& frame = {}) {
  test::gl_context();
  exec::PassLibrary library;
  penumbra::register_shared_passes(library);
  library.add(test::upload_pass_type("upload_input", format, input));
  if (depth) library.add(test::upload_pass_type("upload_depth", Format::R32F, *depth));
  graph::GraphBuilder b("filter");
  graph::TextureHandle in = b.texture("in", format, graph::SizeExpr::screen());
  graph::TextureHandle out = b.texture("out", format, graph::SizeExpr::screen());
  b.pass("upload_input", "upload_input").write("out", in);
  graph::TextureHandle d;
  if (depth) {
    d = b.texture("d", Format::R32F, graph::SizeExpr::screen());
    b.pass("upload_depth", "upload_depth").write("out", d);
  }
  graph::PassBuilder filter = b.pass("separable_filter", "filter");
  filter.read("input", in).write("output", out);
  if (depth) filter.read("depth", d);
  filter.param("axis", std::string("x"));
  for (const auto& [k, v] : params) filter.param(k, v);
  b.output(out);
  graph::GraphDesc g = b.build();
  graph::ParameterSet values(g.parameters);
  auto plan = graph::compile(g, library.declarations(), values, {input.width, input.height, 8});
  for (const graph::GraphError& e : plan.errors()) ADD_FAILURE() << e.to_string();
  if (!plan) return {make_error("no plan", ErrorKind::internal), {}};
  exec::ShaderCache shaders;
  exec::TexturePool pool;
  exec::Executor executor(library, shaders, pool);
  EXPECT_TRUE(executor.set_plan(std::move(*plan)));
  FilterRun run{executor.execute(values, frame), {}};
  if (run.status) run.out = test::read_texture(*executor.resource("out"));
  return run;
}

// kW x kH, `channels` channels; channel c of pixel x is f(x, c), the same on every row.
test::TextureImage image(int channels, const std::function<float(int, int)>& f) {
  test::TextureImage t{kW, kH, channels, {}};
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < channels; ++c) t.texels.push_back(f(x, c));
  return t;
}

TEST(SeparableFilter, BoxAveragesEveryChannelWithClampedEdges) {
  // Channel c of pixel x is (c + 1) * x: a box of radius 1 keeps it inside, clamps at the ends.
  const test::TextureImage in = image(4, [](int x, int c) { return float((c + 1) * x); });
  const FilterRun r = filter_x(Format::RGBA32F, in, {{"mode", std::string("box")}, {"radius", 1}});
  ASSERT_TRUE(r.status) << r.status.error().to_string();
  for (int c = 0; c < 4; ++c) {
    EXPECT_FLOAT_EQ(r.out.at(0, 1, c), (c + 1) * (0 + 0 + 1) / 3.0f) << "left edge clamped, channel " << c;
    EXPECT_FLOAT_EQ(r.out.at(4, 1, c), (c + 1) * 4.0f) << "a ramp's box average is the ramp";
    EXPECT_FLOAT_EQ(r.out.at(8, 1, c), (c + 1) * (7 + 8 + 8) / 3.0f) << "right edge clamped";
  }
}

TEST(SeparableFilter, GaussianWeightsAreTheNormalisedGaussian) {
  // A unit impulse at x = 4 spreads into the kernel's weights.
  const test::TextureImage in = image(2, [](int x, int c) { return x == 4 ? (c == 0 ? 1.0f : 2.0f) : 0.0f; });
  const FilterRun r = filter_x(Format::RG32F, in, {{"mode", std::string("gaussian")}, {"radius", 2}, {"sigma", 1.0}});
  ASSERT_TRUE(r.status) << r.status.error().to_string();
  double total = 0.0;
  for (int i = -2; i <= 2; ++i) total += std::exp(-i * i / 2.0);
  for (int i = -2; i <= 2; ++i) {
    EXPECT_NEAR(r.out.at(4 + i, 0, 0), std::exp(-i * i / 2.0) / total, 1e-6) << "tap " << i;
    EXPECT_NEAR(r.out.at(4 + i, 0, 1), 2.0 * std::exp(-i * i / 2.0) / total, 1e-6) << "tap " << i;
  }
  EXPECT_EQ(r.out.at(1, 0, 0), 0.0f) << "beyond the radius";
}

// A unit impulse at `at` on a width x 1 one-channel row.
test::TextureImage impulse(int width, int at) {
  test::TextureImage t{width, 1, 1, std::vector<float>(size_t(width), 0.0f)};
  t.texels[size_t(at)] = 1.0f;
  return t;
}

// Checks that `run` spread impulse(41, 20) into the normalised gaussian of `sigma` texels over
// ceil(3 sigma) taps each side, and nothing beyond.
void expect_gaussian(const FilterRun& run, double sigma) {
  ASSERT_TRUE(run.status) << run.status.error().to_string();
  const int radius = int(std::ceil(3.0 * sigma));
  double total = 0.0;
  for (int i = -radius; i <= radius; ++i) total += std::exp(-i * i / (2.0 * sigma * sigma));
  for (int i = -radius; i <= radius; ++i)
    EXPECT_NEAR(run.out.at(20 + i, 0, 0), std::exp(-i * i / (2.0 * sigma * sigma)) / total, 1e-5) << "tap " << i;
  if (20 + radius + 1 < run.out.width) {
    EXPECT_EQ(run.out.at(20 + radius + 1, 0, 0), 0.0f) << "beyond the radius";
  }
}

exec::FrameInputs frame_lit_by(float light_size, const scene::ShadowFrustum& shadow) {
  exec::FrameInputs f;
  f.light.size = light_size;
  f.shadow = shadow;
  return f;
}

TEST(SeparableFilter, PenumbraHeightSizesTheGaussianByTheFramesLight) {
  const std::map<std::string, graph::ParamValue> params{
      {"mode", std::string("gaussian")}, {"penumbra_height", 2.0}, {"radius", 1}, {"sigma", 0.5}};
  // No scene: heights are world units and the emitter is 1 unit away (set_shadow_uniforms' fallbacks;
  // a scene's scale is scene::blocker_height_scale, tested in tests/scene). Directional, diameter 0.5,
  // an orthographic map 10 units wide: an edge 2 units high casts a penumbra 2 x 0.5 / 1 = 1 unit wide, 0.1 of
  // the map, 4.1 texels of this 41-texel row; sigma = width / 4, and radius and sigma are overridden.
  expect_gaussian(filter_x(Format::R32F, impulse(41, 20), params, nullptr,
                           frame_lit_by(0.5f, {.near_plane = 1.0f, .far_plane = 9.0f, .orthographic = true,
                                               .width_world = 10.0f})),
                  0.25 * 4.1);
  // Spot, diameter 2, depth range 1..9, 1 unit wide at distance 1: the receiver at the middle (5), the
  // edge at 3: 2 x 2 / 3 = 1.33 units wide at the receiver, where the map is 5 units wide: 0.267 of it.
  expect_gaussian(filter_x(Format::R32F, impulse(41, 20), params, nullptr,
                           frame_lit_by(2.0f, {.near_plane = 1.0f, .far_plane = 9.0f, .orthographic = false,
                                               .tan_half_fov = 0.5f})),
                  0.25 * 41.0 * (2.0 * 2.0 / 3.0) / 5.0);
}

TEST(SeparableFilter, PenumbraHeightsGaussianStopsAtTheLargestRadius) {
  // The directional case above with a light 20 times larger and an edge 2 units high: 2 map widths (20
  // texels of sigma); sigma stays 16 / 3 (radius 16).
  expect_gaussian(filter_x(Format::R32F, impulse(41, 20), {{"mode", std::string("gaussian")}, {"penumbra_height", 2.0}},
                           nullptr,
                           frame_lit_by(10.0f, {.near_plane = 1.0f, .far_plane = 9.0f, .orthographic = true,
                                               .width_world = 10.0f})),
                  16.0 / 3.0);
}

TEST(SeparableFilter, MinAndMaxPerChannelOnSixteenBitNormalisedFormats) {
  // Channel 0 has a dip at x = 4, channel 1 a peak: min and max act on each channel alone.
  const auto f = [](int x, int c) { return c == 0 ? (x == 4 ? -0.5f : 0.5f) : (x == 4 ? 0.75f : -0.25f); };
  const FilterRun lo = filter_x(Format::RGBA16_SNORM, image(4, f), {{"mode", std::string("min")}, {"radius", 1}});
  ASSERT_TRUE(lo.status) << lo.status.error().to_string();
  const FilterRun hi = filter_x(Format::RGBA16_SNORM, image(4, f), {{"mode", std::string("max")}, {"radius", 1}});
  ASSERT_TRUE(hi.status) << hi.status.error().to_string();
  for (int x : {3, 4, 5}) {
    EXPECT_NEAR(lo.out.at(x, 2, 0), -0.5f, 1e-4) << x;
    EXPECT_NEAR(lo.out.at(x, 2, 1), -0.25f, 1e-4) << x;
    EXPECT_NEAR(hi.out.at(x, 2, 0), 0.5f, 1e-4) << x;
    EXPECT_NEAR(hi.out.at(x, 2, 1), 0.75f, 1e-4) << x;
  }
  EXPECT_NEAR(lo.out.at(2, 2, 0), 0.5f, 1e-4) << "out of the dip's reach";

  const FilterRun unorm = filter_x(Format::RGBA16, image(4, [](int x, int) { return x == 0 ? 1.0f : 0.0f; }),
                             {{"mode", std::string("max")}, {"radius", 1}});
  ASSERT_TRUE(unorm.status) << unorm.status.error().to_string();
  EXPECT_EQ(unorm.out.at(1, 0, 3), 1.0f);
  EXPECT_EQ(unorm.out.at(2, 0, 3), 0.0f);
}

TEST(SeparableFilter, BilateralStopsAtADepthEdge) {
  // Value 0 left of x = 4.5, 1 right of it; depth steps there too. A plain gaussian blurs the
  // step, the bilateral one keeps both sides (their taps across the edge weigh exp(-50)).
  const test::TextureImage in = image(1, [](int x, int) { return x <= 4 ? 0.0f : 1.0f; });
  const test::TextureImage depth = image(1, [](int x, int) { return x <= 4 ? 1.0f : 2.0f; });
  const std::map<std::string, graph::ParamValue> params{
      {"mode", std::string("bilateral")}, {"radius", 3}, {"sigma", 2.0}, {"depth_sigma", 0.1}};
  const FilterRun r = filter_x(Format::R32F, in, params, &depth);
  ASSERT_TRUE(r.status) << r.status.error().to_string();
  EXPECT_NEAR(r.out.at(4, 1, 0), 0.0f, 1e-6);
  EXPECT_NEAR(r.out.at(5, 1, 0), 1.0f, 1e-6);
  const FilterRun plain = filter_x(Format::R32F, in, {{"mode", std::string("gaussian")}, {"radius", 3}, {"sigma", 2.0}});
  ASSERT_TRUE(plain.status);
  EXPECT_GT(plain.out.at(4, 1, 0), 0.2f) << "the plain gaussian does blur across";
}

TEST(SeparableFilter, BilateralWithoutDepthIsRefusedWithTheReason) {
  const FilterRun r = filter_x(Format::R16F, image(1, [](int, int) { return 0.5f; }), {{"mode", std::string("bilateral")}});
  ASSERT_FALSE(r.status);
  EXPECT_NE(r.status.error().to_string().find("bind the 'depth' slot"), std::string::npos) << r.status.error().to_string();
}

}  // namespace
