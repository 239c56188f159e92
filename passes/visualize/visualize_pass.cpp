// Debug view of a single-channel resource (compute). See visualize.comp.glsl for the mapping.
#include "passes/visualize/visualize_pass.h"

#include <optional>

namespace penumbra::passes {
namespace {

using graph::Access;
using graph::Format;
using graph::ParamDesc;
using graph::ParamType;
using graph::SlotKind;
using graph::Usage;

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
  graph::PassTypeDecl d;
  d.name = "visualize";
  d.description = "Single-channel texture to RGBA8 with a grey or heat colour map over [min, max] (compute)";
  d.slots = {
      {"input", Access::read, SlotKind::texture, {Format::R8, Format::R16F, Format::R32F, Format::DEPTH32F},
       Usage::sampled, true},
      {"output", Access::write, SlotKind::texture, {Format::RGBA8}, Usage::image_store, true},
  };
  ParamDesc colormap{.name = "colormap", .type = ParamType::enumeration, .default_value = std::string("grey")};
  colormap.options = {"grey", "heat"};
  colormap.description = "grey: black at min, white at max; heat: blue, cyan, green, yellow, red";
  ParamDesc lo{.name = "min", .type = ParamType::real, .default_value = 0.0};
  lo.description = "Value shown as the colour map's start (input units)";
  ParamDesc hi{.name = "max", .type = ParamType::real, .default_value = 1.0};
  hi.description = "Value shown as the colour map's end (input units)";
  ParamDesc linear{.name = "linearize_depth", .type = ParamType::boolean, .default_value = false};
  linear.description = "DEPTH32F input: convert perspective window depth to distance with near/far";
  ParamDesc near_plane{.name = "near", .type = ParamType::real, .default_value = 0.1, .min = 1e-6, .max = 1e6};
  near_plane.unit = "world units";
  near_plane.description = "Near plane distance for linearize_depth";
  ParamDesc far_plane{.name = "far", .type = ParamType::real, .default_value = 100.0, .min = 1e-6, .max = 1e6};
  far_plane.unit = "world units";
  far_plane.description = "Far plane distance for linearize_depth";
  d.params = {colormap, lo, hi, linear, near_plane, far_plane};
  return {d, [] { return std::make_unique<VisualizePass>(); }};
}

}  // namespace penumbra::passes
