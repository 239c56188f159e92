// Fixed-kernel PCF (compute): box N x N or a per-pixel rotated Vogel disk, hardware comparison
// per tap, receiver-plane bias. The kernel is a compile-time variant of one shader, chosen per
// frame from the live `kernel` parameter, so switching kernels never recompiles the graph.
#include "passes/pcf_mask/pcf_mask_pass.h"

#include <optional>

#include "passes/common/shadow_uniforms.h"

namespace penumbra::passes {
namespace {

using graph::Access;
using graph::Format;
using graph::ParamDesc;
using graph::ParamType;
using graph::SlotKind;
using graph::Usage;

constexpr const char* kShader = "passes/pcf_mask/pcf_mask.comp.glsl";

class PcfMaskPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const bool box = ctx.enumeration("kernel") == "box";
    const int box_size = ctx.integer("box_size");
    if (box && box_size % 2 == 0) {
      // The parameter range cannot say "odd"; the executor prefixes the pass name.
      return make_error("parameter 'box_size' must be odd (the box is centred on the receiver), got " +
                        std::to_string(box_size) + "; valid: 1, 3, ..., 15");
    }
    gl::ShaderProgram& p = ctx.program({.compute = kShader, .defines = {{"PCF_KERNEL_BOX", box ? "1" : "0"}}});
    if (!p.valid()) return *p.last_error();
    if (!compare_) compare_.emplace(gl::Sampler::Filter::linear, gl::Sampler::Wrap::clamp, true);
    ctx.bind_sampled(p, "u_position", "position");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", compare_->id());
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    set_shadow_uniforms(p.program(), ctx.frame());
    const gl::Program& prog = p.program();
    prog.set("u_depth_bias", ctx.real("depth_bias"));
    prog.set("u_box_size", box_size);
    prog.set("u_samples", ctx.integer("samples"));
    prog.set("u_radius", ctx.real("radius"));
    gl::Texture& mask = ctx.texture("mask");
    ctx.dispatch_over(p, mask.width(), mask.height());
    return {};
  }

 private:
  std::optional<gl::Sampler> compare_;  // created on first use, when a context is current
};

}  // namespace

exec::PassType pcf_mask_pass_type() {
  graph::PassTypeDecl d;
  d.name = "pcf_mask";
  d.description = "Percentage-closer filtering with a box or rotated Vogel-disk kernel (compute)";
  d.slots = {
      {"position", Access::read, SlotKind::texture, {Format::RGBA32F}, Usage::sampled, true},
      {"normal", Access::read, SlotKind::texture, {Format::RGBA16F, Format::RGBA32F}, Usage::sampled, true},
      {"shadow_map", Access::read, SlotKind::texture, {Format::DEPTH32F}, Usage::sampled, true},
      {"light", Access::read, SlotKind::imported, {}, Usage::imported, false},
      {"mask", Access::write, SlotKind::texture, {Format::R16F}, Usage::image_store, true},
  };
  d.same_size_groups = {{"position", "normal", "mask"}};
  ParamDesc kernel{.name = "kernel", .type = ParamType::enumeration, .default_value = std::string("box")};
  kernel.options = {"box", "vogel"};
  kernel.description = "box: N x N taps one texel apart; vogel: rotated Vogel disk";
  ParamDesc box{.name = "box_size", .type = ParamType::integer, .default_value = 5, .min = 1, .max = 15};
  box.unit = "texels";
  box.description = "Box kernel width N (odd)";
  ParamDesc samples{.name = "samples", .type = ParamType::integer, .default_value = 16, .min = 1, .max = 64};
  samples.description = "Vogel-disk taps";
  ParamDesc radius{.name = "radius", .type = ParamType::real, .default_value = 2.5, .min = 0.0, .max = 64.0};
  radius.unit = "texels";
  radius.description = "Vogel-disk radius";
  ParamDesc bias{.name = "depth_bias", .type = ParamType::real, .default_value = 0.0002, .min = 0.0, .max = 0.05};
  bias.unit = "window depth";
  bias.description = "Constant bias subtracted from the receiver-plane depth of every tap";
  d.params = {kernel, box, samples, radius, bias};
  return {d, [] { return std::make_unique<PcfMaskPass>(); }};
}

}  // namespace penumbra::passes
