// Binary shadow mask from one shadow-map comparison per pixel (compute).
#include "passes/hard_mask/hard_mask_pass.h"

#include "passes/common/shadow_uniforms.h"

namespace penumbra::passes {
namespace {

using graph::Access;
using graph::Format;
using graph::ParamDesc;
using graph::ParamType;
using graph::SlotKind;
using graph::Usage;

class HardMaskPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "passes/hard_mask/hard_mask.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_position", "position");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map");
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    set_shadow_uniforms(p.program(), ctx.frame());
    p.program().set("u_depth_bias", ctx.real("depth_bias"));
    gl::Texture& mask = ctx.texture("mask");
    ctx.dispatch_over(p, mask.width(), mask.height());
    return {};
  }
};

}  // namespace

exec::PassType hard_mask_pass_type() {
  graph::PassTypeDecl d;
  d.name = "hard_mask";
  d.description = "Binary shadow mask: one nearest shadow-map comparison per pixel (compute)";
  d.slots = {
      {"position", Access::read, SlotKind::texture, {Format::RGBA32F}, Usage::sampled, true},
      {"shadow_map", Access::read, SlotKind::texture, {Format::DEPTH32F}, Usage::sampled, true},
      {"light", Access::read, SlotKind::imported, {}, Usage::imported, false},
      {"mask", Access::write, SlotKind::texture, {Format::R16F}, Usage::image_store, true},
  };
  d.same_size_groups = {{"position", "mask"}};
  ParamDesc bias{.name = "depth_bias", .type = ParamType::real, .default_value = 0.0005, .min = 0.0, .max = 0.05};
  bias.unit = "window depth";
  bias.description = "Subtracted from the receiver depth before the comparison";
  d.params = {bias};
  return {d, [] { return std::make_unique<HardMaskPass>(); }};
}

}  // namespace penumbra::passes
