// The frame's last pass (technique/frame_graph.h): lights the G-buffer with the technique's
// shadow_mask. Compute, one thread per pixel.
#include "passes/lighting/lighting_pass.h"

#include <cmath>

#include "exec/pass_decl_builder.h"
#include "passes/common/shadow_uniforms.h"

namespace penumbra::passes {
namespace {

using graph::Format;

class LightingPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "passes/lighting/lighting.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    const exec::FrameInputs& f = ctx.frame();
    ctx.bind_sampled(p, "u_albedo", "albedo");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_shadow_mask", "shadow_mask");
    ctx.bind_image(0, "color", GL_WRITE_ONLY);
    const gl::Program& prog = p.program();
    prog.set("u_light_dir", f.light.direction);
    prog.set("u_light_pos", f.light.position);
    prog.set("u_light_color", f.light.color * f.light.intensity);
    prog.set("u_light_spot", f.light.type == scene::LightType::spot ? 1 : 0);
    prog.set("u_light_point", f.light.type == scene::LightType::point ? 1 : 0);
    prog.set("u_spot_cos", std::cos(f.light.spot_angle));
    prog.set("u_ambient", ctx.real("ambient"));
    // The cascade debug view (scene::CascadeSettings::tint) picks cascades as the filters do.
    if (Status s = set_shadow_uniforms(prog, f, SixFaces::read); !s) return s;
    prog.set("u_cascade_tint", f.cascades.tint ? 1 : 0);
    gl::Texture& color = ctx.texture("color");
    ctx.dispatch_over(p, color.width(), color.height());
    return {};
  }
};

}  // namespace

exec::PassType lighting_pass_type() {
  return exec::PassDeclBuilder("lighting")
      .describe("Lambert + ambient, shadowed by shadow_mask, tone mapped to RGBA8 (compute)")
      .sampled("albedo")
      .sampled("normal")
      .sampled("depth", {Format::R32F})
      .sampled("shadow_mask", {Format::R8, Format::R16F, Format::R32F})
      .imported("light")
      .image_out("color", {Format::RGBA8})
      .same_size({"albedo", "normal", "depth", "shadow_mask", "color"})
      .real("ambient", 0.25, 0.0, 2.0, "", "Ambient term added to the shadowed direct light")
      .side_effect()
      .build<LightingPass>();
}

}  // namespace penumbra::passes
