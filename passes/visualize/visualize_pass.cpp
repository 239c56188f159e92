// Debug view of a single-channel resource (compute). See visualize.comp.glsl for the mapping.
#include "passes/visualize/visualize_pass.h"

#include <optional>

#include "exec/pass_decl_builder.h"

namespace penumbra::passes {
namespace {

using graph::Format;

class VisualizePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "passes/visualize/visualize.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    // Plain reads even from a depth texture another pass samples with comparison.
    if (!nearest_) nearest_.emplace(gl::Sampler::Filter::nearest, gl::Sampler::Wrap::clamp, false);
    ctx.bind_sampled(p, "u_input", "input", nearest_->id());
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    const gl::Program& prog = p.program();
    const bool depth = ctx.texture("input").format() == gl::Format::DEPTH32F;
    prog.set("u_min", ctx.real("min"));
    prog.set("u_max", ctx.real("max"));
    prog.set("u_heat", ctx.enumeration("colormap") == "heat" ? 1 : 0);
    prog.set("u_linearize_depth", depth && ctx.boolean("linearize_depth") ? 1 : 0);
    prog.set("u_near", ctx.real("near"));
    prog.set("u_far", ctx.real("far"));
    gl::Texture& out = ctx.texture("output");
    ctx.dispatch_over(p, out.width(), out.height());
    return {};
  }

 private:
  std::optional<gl::Sampler> nearest_;
};

}  // namespace

exec::PassType visualize_pass_type() {
  return exec::PassDeclBuilder("visualize")
      .describe("Single-channel texture to RGBA8 with a grey or heat colour map over [min, max] (compute)")
      .sampled("input", {Format::R8, Format::R16F, Format::R32F, Format::DEPTH32F})
      .image_out("output", {Format::RGBA8})
      .enumeration("colormap", "grey", {"grey", "heat"},
                   "grey: black at min, white at max; heat: blue, cyan, green, yellow, red")
      .real("min", 0.0, 0.0, 0.0, "", "Value shown as the colour map's start (input units)")
      .real("max", 1.0, 0.0, 0.0, "", "Value shown as the colour map's end (input units)")
      .boolean("linearize_depth", false, "DEPTH32F input: convert perspective window depth to distance with near/far")
      .real("near", 0.1, 1e-6, 1e6, "world units", "Near plane distance for linearize_depth")
      .real("far", 100.0, 1e-6, 1e6, "world units", "Far plane distance for linearize_depth")
      .build<VisualizePass>();
}

}  // namespace penumbra::passes
