// Binary shadow mask from one shadow-map comparison per pixel (compute).
#include "passes/hard_mask/hard_mask_pass.h"

#include "exec/pass_decl_builder.h"
#include "passes/common/shadow_receiver_decl.h"
#include "passes/common/shadow_uniforms.h"

namespace penumbra::passes {
namespace {

using graph::Format;

class HardMaskPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    // The mask is exactly 0 or 1: R8 holds it as well as R16F, in half the bytes.
    gl::ShaderProgram& p = ctx.program(
        {.compute = "passes/hard_mask/hard_mask.comp.glsl",
         .defines = {{"MASK_QUALIFIER", graph::image_format_qualifier(ctx.texture("mask").format())}}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map");
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    if (Status s = set_shadow_uniforms(p.program(), ctx.frame(), SixFaces::read); !s) return s;
    p.program().set("u_depth_bias", ctx.real("depth_bias"));
    gl::Texture& mask = ctx.texture("mask");
    ctx.dispatch_over(p, mask.width(), mask.height());
    return {};
  }
};

}  // namespace

exec::PassType hard_mask_pass_type() {
  return shadow_receiver_pass("hard_mask", "Binary shadow mask: one nearest shadow-map comparison per pixel (compute)")
      .image_out("mask", {Format::R8, Format::R16F})
      .same_size({"depth", "normal", "mask"})
      .real("depth_bias", 0.0005, 0.0, 0.05, "window depth",
            "Subtracted from the receiver depth before the comparison")
      .build<HardMaskPass>();
}

}  // namespace penumbra::passes
