#include "tiny_technique.h"

namespace penumbra::sandbox_test {
namespace {

using graph::Access;
using graph::Format;
using graph::ParamDesc;
using graph::ParamType;
using graph::SlotKind;
using graph::Usage;

class FillPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    // Lets the tests see what the sandbox does with a frame a pass refuses as bad input.
    if (ctx.boolean("refuse")) return make_error("sandbox_tiny: 'refuse' is on, so this frame is refused");
    gl::ShaderProgram& p = ctx.program({.compute = "tests/sandbox/shaders/tiny_fill.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "depth", "depth");
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    p.program().set("level", ctx.real("level"));
    p.program().set("stripe_width", ctx.integer("stripe_width"));
    p.program().set("pattern", ctx.enumeration("pattern") == "checker" ? 1 : 0);
    ctx.dispatch_over(p, ctx.texture("mask").width(), ctx.texture("mask").height());
    return {};
  }
};

class ScalePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "tests/sandbox/shaders/tiny_scale.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "src", "input");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    p.program().set("factor", ctx.real("factor"));
    ctx.dispatch_over(p, ctx.texture("output").width(), ctx.texture("output").height());
    return {};
  }
};

void register_passes(exec::PassLibrary& library) {
  graph::PassTypeDecl fill;
  fill.name = "sandbox_test_fill";
  fill.slots = {{"depth", Access::read, SlotKind::texture, {Format::R32F}, Usage::sampled, true},
                {"mask", Access::write, SlotKind::texture, {Format::R16F}, Usage::image_store, true}};
  fill.params = {
      ParamDesc{.name = "level", .type = ParamType::real, .default_value = 0.5, .min = 0.0, .max = 1.0},
      ParamDesc{.name = "stripe_width", .type = ParamType::integer, .default_value = 8, .min = 1, .max = 64},
      ParamDesc{.name = "pattern", .type = ParamType::enumeration, .default_value = std::string("stripes"),
                .options = {"stripes", "checker"}},
      ParamDesc{.name = "refuse", .type = ParamType::boolean, .default_value = false}};
  fill.same_size_groups = {{"depth", "mask"}};
  library.add({fill, [] { return std::make_unique<FillPass>(); }});

  graph::PassTypeDecl scale;
  scale.name = "sandbox_test_scale";
  scale.slots = {{"input", Access::read, SlotKind::texture, {Format::R16F}, Usage::sampled, true},
                 {"output", Access::write, SlotKind::texture, {Format::R16F}, Usage::image_store, true}};
  scale.params = {ParamDesc{.name = "factor", .type = ParamType::real, .default_value = 1.0, .min = 0.0, .max = 1.0}};
  scale.same_size_groups = {{"input", "output"}};
  library.add({scale, [] { return std::make_unique<ScalePass>(); }});
}

}  // namespace

void register_tiny_technique(technique::TechniqueRegistry& registry) {
  registry.add({.name = kTinyTechnique,
                .graph_file = "tests/sandbox/tiny_technique.json",
                .register_passes = register_passes});
}

}  // namespace penumbra::sandbox_test
