// The frame's last pass (plugin/frame_graph.h): lights the G-buffer with the technique's
// shadow_mask. Compute, one thread per pixel.
#include "passes/lighting/lighting_pass.h"

#include <cmath>

namespace penumbra::passes {
namespace {

using graph::Access;
using graph::Format;
using graph::ParamDesc;
using graph::ParamType;
using graph::SlotKind;
using graph::Usage;

class LightingPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "passes/lighting/lighting.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    const exec::FrameInputs& f = ctx.frame();
    ctx.bind_sampled(p, "u_albedo", "albedo");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_position", "position");
    ctx.bind_sampled(p, "u_shadow_mask", "shadow_mask");
    ctx.bind_image(0, "color", GL_WRITE_ONLY);
    const gl::Program& prog = p.program();
    prog.set("u_light_dir", f.light.direction);
    prog.set("u_light_pos", f.light.position);
    prog.set("u_light_color", f.light.color * f.light.intensity);
    prog.set("u_light_spot", f.light.type == scene::LightType::spot ? 1 : 0);
    prog.set("u_spot_cos", std::cos(f.light.spot_angle));
    prog.set("u_ambient", ctx.real("ambient"));
    gl::Texture& color = ctx.texture("color");
    ctx.dispatch_over(p, color.width(), color.height());
    return {};
  }
};

}  // namespace

exec::PassType lighting_pass_type() {
  graph::PassTypeDecl d;
  d.name = "lighting";
  d.description = "Lambert + ambient, shadowed by shadow_mask, tone mapped to RGBA8 (compute)";
  d.slots = {
      {"albedo", Access::read, SlotKind::texture, {}, Usage::sampled, true},
      {"normal", Access::read, SlotKind::texture, {}, Usage::sampled, true},
      {"position", Access::read, SlotKind::texture, {}, Usage::sampled, true},
      {"shadow_mask", Access::read, SlotKind::texture, {Format::R8, Format::R16F, Format::R32F}, Usage::sampled, true},
      {"light", Access::read, SlotKind::imported, {}, Usage::imported, true},
      {"color", Access::write, SlotKind::texture, {Format::RGBA8}, Usage::image_store, true},
  };
  d.same_size_groups = {{"albedo", "normal", "position", "shadow_mask", "color"}};
  ParamDesc ambient{.name = "ambient", .type = ParamType::real, .default_value = 0.25, .min = 0.0, .max = 2.0};
  ambient.description = "Ambient term added to the shadowed direct light (unitless)";
  d.params = {ambient};
  d.side_effect = true;
  return {d, [] { return std::make_unique<LightingPass>(); }};
}

}  // namespace penumbra::passes
