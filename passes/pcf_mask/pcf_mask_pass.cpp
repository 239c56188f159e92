// Fixed-kernel PCF (compute): box N x N or a per-pixel rotated Vogel disk, hardware comparison
// per tap, receiver-plane bias. The kernel is a compile-time variant of one shader, chosen per
// frame from the live `kernel` parameter, so switching kernels never recompiles the graph.
#include "passes/pcf_mask/pcf_mask_pass.h"

#include <optional>

#include "exec/pass_decl_builder.h"
#include "passes/common/shadow_receiver_decl.h"
#include "passes/common/shadow_uniforms.h"
#include "passes/sampling/rotation_noise.h"
#include "passes/shadow_tiles/tiled_dispatch.h"

namespace penumbra::passes {
namespace {

using graph::Format;

constexpr const char* kShader = "passes/pcf_mask/pcf_mask.comp.glsl";

class PcfMaskPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const bool box = ctx.enumeration("kernel") == "box";
    if (Status filled = fill_constant_tiles(ctx, {{"mask", glm::vec4(1.0f), glm::vec4(0.0f)}}); !filled) return filled;
    gl::ShaderProgram& p =
        ctx.program({.compute = kShader, .defines = tile_defines(ctx, {{"PCF_KERNEL_BOX", box ? "1" : "0"}})});
    if (!p.valid()) return *p.last_error();
    if (!compare_) compare_.emplace(gl::Sampler::Filter::linear, gl::Sampler::Wrap::clamp, true);
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", compare_->id());
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    if (Status s = set_shadow_uniforms(p.program(), ctx.frame(), SixFaces::read); !s) return s;
    const gl::Program& prog = p.program();
    prog.set("u_depth_bias", ctx.real("depth_bias"));
    prog.set("u_box_size", ctx.integer("box_size"));  // odd: the declaration's step
    prog.set("u_samples", ctx.integer("samples"));
    prog.set("u_radius", ctx.real("radius"));
    set_rotation_noise(prog, ctx);
    gl::Texture& mask = ctx.texture("mask");
    dispatch_screen(ctx, p, mask.width(), mask.height());
    return {};
  }

 private:
  std::optional<gl::Sampler> compare_;  // created on first use, when a context is current
};

}  // namespace

exec::PassType pcf_mask_pass_type() {
  exec::PassDeclBuilder b =
      shadow_receiver_pass("pcf_mask", "Percentage-closer filtering with a box or rotated Vogel-disk kernel (compute)");
  add_tile_slots(b);
  return b.image_out("mask", {Format::R16F})
      .same_size({"depth", "normal", "mask"})
      .enumeration("kernel", "box", {"box", "vogel"},
                   "box: N x N taps one texel apart; vogel: Vogel disk rotated per receiver by interleaved gradient noise")
      .integer("box_size", 5, 1, 15, "texels", "Box kernel width N (odd; kernel = box)").step(2)
      .integer("samples", 16, 1, 64, "", "Vogel-disk taps (kernel = vogel)")
      .real("radius", 2.5, 0.0, 64.0, "texels", "Vogel-disk radius (kernel = vogel)")
      .param(rotation_noise_param())
      .real("depth_bias", 0.0002, 0.0, 0.05, "window depth",
            "Constant bias subtracted from the receiver-plane depth of every tap")
      .build<PcfMaskPass>();
}

}  // namespace penumbra::passes
