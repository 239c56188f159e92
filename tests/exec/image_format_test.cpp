// An image's declared format qualifier against the texture bound to its unit: the pass is
// refused with an error naming both (GL itself converts silently and the pass stores garbage),
// an R32F texture bound as r32ui for atomics (bind_image_bits), and how the qualifiers are read
// from a shader's text.
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "exec/executor.h"
#include "exec/pass_decl_builder.h"
#include "gl/image_declarations.h"
#include "graph/builder.h"
#include "graph/compiler.h"
#include "test_support/gl_context.h"
#include "test_support/read_back.h"
#include "test_passes.h"

using namespace penumbra;
using namespace penumbra::graph;

namespace {

// tests/exec/shaders/add.comp.glsl declares its output r32f; this pass type lets the graph bind
// an R16F texture there, which only the qualifier check catches.
class AddAnyPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "tests/exec/shaders/add.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_src", "in");
    ctx.bind_image(0, "out", GL_WRITE_ONLY);
    p.program().set("u_amount", 1.0f);
    ctx.dispatch_over(p, ctx.texture("out"));
    return {};
  }
};

// Compiles `g` at 8 x 8 against the test passes and `pass_types`, and runs one frame; `after`
// sees the executor then.
Status compile_and_run(const std::vector<exec::PassType>& pass_types, const GraphDesc& g,
                       const std::function<void(exec::Executor&)>& after = {}) {
  exec::PassLibrary library;
  test::register_test_passes(library);
  for (const exec::PassType& t : pass_types) library.add(t);
  ParameterSet params(g.parameters);
  auto plan = compile(g, library.declarations(), params, {8, 8, 8});
  if (!plan) return make_error("the test graph does not compile: " + plan.errors().front().to_string());
  exec::ShaderCache shaders;
  exec::TexturePool pool;
  exec::Executor executor(library, shaders, pool);
  if (Status s = executor.set_plan(std::move(*plan)); !s) return s;
  Status s = executor.execute(params, exec::FrameInputs{});
  if (s && after) after(executor);
  return s;
}

Status run_with_output(Format output) {
  GraphBuilder b("qualifier");
  TextureHandle a = b.texture("a", Format::R32F, SizeExpr::fixed(8, 8));
  TextureHandle out = b.texture("out", output, SizeExpr::fixed(8, 8));
  b.pass("fill", "fill").write("out", a).param("value", 1.0);
  b.pass("add_any", "add").read("in", a).write("out", out);
  b.output(out);
  return compile_and_run({exec::PassDeclBuilder("add_any")
                              .describe("test: add.comp.glsl with any float output format")
                              .sampled("in", {Format::R32F})
                              .image_out("out", {Format::R32F, Format::R16F})
                              .build<AddAnyPass>()},
                         b.build());
}

// MaxBitsPass binds its slot with bind_image_bits: an R32F texture's storage as r32ui, so that a
// shader can MAX non-negative floats into it with image atomics (esm's compute silhouette
// writer); another format is refused with an error naming the slot and the format.
class MaxBitsPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "tests/exec/shaders/max_bits.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_image_bits(0, "img", GL_READ_WRITE);
    p.program().set("u_low", 0.25f);
    p.program().set("u_high", 2.0f);
    ctx.dispatch_over(p, ctx.texture("img"));
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    return {};
  }
};

struct BitsRun {
  Status status;
  metrics::MaskImage image;
};

BitsRun run_on(Format format) {
  const std::vector<exec::PassType> max_bits = {
      exec::PassDeclBuilder("max_bits")
          .describe("test: max_bits.comp.glsl, atomic MAX of float bits into a filled texture")
          .image_inout("img", {Format::R32F})
          .build<MaxBitsPass>(),
      exec::PassDeclBuilder("max_bits_first")
          .describe("test: max_bits.comp.glsl as the first writer, any float format")
          .image_out("img", {Format::R32F, Format::R16F})
          .build<MaxBitsPass>()};
  GraphBuilder b("bits");
  TextureHandle a = b.texture("a", format, SizeExpr::fixed(8, 8));
  if (format == Format::R32F) {
    b.pass("fill", "fill").write("out", a).param("value", 0.5);  // fill's output is R32F only
    b.pass("max_bits", "max").read_write("img", a);
  } else {
    b.pass("max_bits_first", "max").write("img", a);
  }
  b.output(a);
  BitsRun run;
  run.status = compile_and_run(max_bits, b.build(), [&](exec::Executor& e) {
    if (gl::Texture* t = e.resource("a")) run.image = test::read_channel(*t);
  });
  return run;
}

}  // namespace

TEST(ImageQualifier, MatchingFormatRuns) {
  test::gl_context();
  Status s = run_with_output(Format::R32F);
  EXPECT_TRUE(s) << s.error().to_string();
}

TEST(ImageQualifier, AnotherFormatIsRefusedNamingBoth) {
  test::gl_context();
  Status s = run_with_output(Format::R16F);
  ASSERT_FALSE(s);
  const std::string text = s.error().to_string();
  EXPECT_NE(text.find("pass 'add'"), std::string::npos) << text;
  EXPECT_NE(text.find("declared r32f"), std::string::npos) << text;
  EXPECT_NE(text.find("slot 'out'"), std::string::npos) << text;
  EXPECT_NE(text.find("R16F"), std::string::npos) << text;
}

TEST(ImageBits, AtomicMaxOfFloatBitsIsTheMaxOfTheFloats) {
  test::gl_context();
  const BitsRun r = run_on(Format::R32F);
  ASSERT_TRUE(r.status) << r.status.error().to_string();
  ASSERT_EQ(r.image.pixels.size(), 64u);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const float filled = 0.5f + 0.001f * static_cast<float>(x);  // tests/exec/shaders/fill.frag.glsl
      EXPECT_FLOAT_EQ(r.image.at(x, y), x < 4 ? filled : 2.0f) << x << ", " << y;
    }
}

TEST(ImageBits, ATextureOtherThanR32FIsRefusedNamingIt) {
  test::gl_context();
  const BitsRun r = run_on(Format::R16F);
  ASSERT_FALSE(r.status);
  const std::string text = r.status.error().to_string();
  EXPECT_NE(text.find("slot 'img'"), std::string::npos) << text;
  EXPECT_NE(text.find("r32ui"), std::string::npos) << text;
  EXPECT_NE(text.find("R16F"), std::string::npos) << text;
}

TEST(ImageDeclarations, ReadsBindingQualifierAndNameThroughDefines) {
  const std::string glsl =
      "#version 450 core\n"
      "#define MASK_QUALIFIER r8\n"
      "layout(local_size_x = 16, local_size_y = 16) in;\n"
      "layout(rgba16f, binding = 2) uniform writeonly image2D u_out;\n"
      "layout(binding = 0, MASK_QUALIFIER) uniform restrict writeonly image2D u_mask;\n"
      "#if A\n"
      "layout(rg16f, binding = 1) uniform readonly image2D u_x;\n"
      "#else\n"
      "layout(r16f, binding = 1) uniform readonly image2D u_x;\n"
      "#endif\n"
      "layout(r32f) uniform image2D u_unbound;\n"
      "uniform sampler2D u_tex;\n";
  const auto d = gl::image_declarations(glsl);
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[0].binding, 2u);
  EXPECT_EQ(d[0].qualifier, "rgba16f");
  EXPECT_EQ(d[0].name, "u_out");
  EXPECT_EQ(d[1].binding, 0u);
  EXPECT_EQ(d[1].qualifier, "r8");
  EXPECT_EQ(d[2].qualifier, "rg16f");
  EXPECT_EQ(d[3].qualifier, "r16f");
  EXPECT_EQ(d[3].binding, 1u);
}

TEST(ImageDeclarations, EveryFormatHasTheQualifierGlslSpells) {
  EXPECT_STREQ(image_format_qualifier(Format::RGB10A2), "rgb10_a2");
  EXPECT_STREQ(image_format_qualifier(Format::R11G11B10F), "r11f_g11f_b10f");
  EXPECT_STREQ(image_format_qualifier(Format::RG16_SNORM), "rg16_snorm");
  EXPECT_STREQ(image_format_qualifier(Format::DEPTH32F), "");
}
