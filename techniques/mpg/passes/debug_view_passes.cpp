// The mpg debug views the sandbox shows: D as a colour gradient (the paper's tuning aid, section
// 3.1) and Figure 4's penumbra/umbra view (distance_view.comp.glsl, penumbra_view.comp.glsl).
#include <glad/gl.h>

#include "techniques/mpg/passes/mpg_pass_common.h"
#include "techniques/mpg/passes/mpg_pass_types.h"

namespace penumbra::mpg {
namespace {

using graph::Format;

class DistanceViewPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = std::string(kShaderDir) + "distance_view.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_distance_map", "input");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    // D counts passes for the multi-pass alteration and kernel pixels for the others.
    const bool passes = ctx.enumeration("alteration") == "multipass";
    p.program().set("u_max_control", static_cast<float>(ctx.integer(passes ? "max_passes" : "max_kernel")));
    ctx.dispatch_over(p, ctx.texture("output"));
    return {};
  }
};

class PenumbraViewPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = std::string(kShaderDir) + "penumbra_view.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_mask", "mask");
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    ctx.dispatch_over(p, ctx.texture("output"));
    return {};
  }
};

}  // namespace

exec::PassType distance_view_pass_type() {
  exec::PassDeclBuilder b("mpg_distance_view");
  b.describe("mpg debug: D as a colour gradient (Cherry & Kooima 3.1)")
      .sampled("input", {Format::RGBA16F})
      .image_out("output", {Format::RGBA8})
      .same_size({"input", "output"})
      .enumeration("alteration", "multipass", {"pcf", "gaussian", "multipass"}, "What D counts")
      .integer("max_passes", 10, 1, kMaxPasses, "", "Top of the gradient (multi-pass)");
  add_max_kernel(b);
  return b.build<DistanceViewPass>();
}

exec::PassType penumbra_view_pass_type() {
  return exec::PassDeclBuilder("mpg_penumbra_view")
      .describe("mpg debug: Figure 4, penumbra marked with a dark gradient, umbra shaded (Cherry & Kooima 4.2)")
      .sampled("mask", {Format::R8, Format::R16F, Format::R32F})
      .sampled("depth", {Format::R32F})
      .image_out("output", {Format::RGBA8})
      .same_size({"mask", "depth", "output"})
      .build<PenumbraViewPass>();
}

}  // namespace penumbra::mpg
