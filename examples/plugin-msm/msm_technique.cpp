#include "msm_technique.h"

#include "exec/pass_decl_builder.h"
#include "msm_quantization.h"
#include "passes/common/shadow_uniforms.h"
#include "passes/shadow_map/light_view_pass.h"

namespace msm {
namespace {

using penumbra::Status;
using penumbra::exec::PassContext;
using penumbra::graph::Format;

class MaskPass final : public penumbra::exec::PassImpl {
 public:
  Status execute(PassContext& ctx) override {
    const bool contact_hardening = ctx.bound("moments_wide");
    penumbra::gl::ShaderProgram& p = ctx.program(
        {.compute = "msm/msm_mask.comp.glsl", .defines = {{"CONTACT_HARDENING", contact_hardening ? "1" : "0"}}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_moments", "moments", bilinear_.id());  // the paper filters bilinearly too
    if (contact_hardening) ctx.bind_sampled(p, "u_moments_wide", "moments_wide", bilinear_.id());
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    if (Status s = penumbra::passes::set_shadow_uniforms(p.program(), ctx.frame()); !s) return s;
    p.program().set("u_to_canonical", kToCanonical);
    p.program().set("u_optimised_offset", kOptimisedOffset);
    p.program().set("u_moment_bias", ctx.real("moment_bias"));
    p.program().set("u_depth_bias", ctx.real("depth_bias"));
    p.program().set("u_narrow_height", ctx.real("narrow_height"));
    p.program().set("u_wide_height", ctx.real("wide_height"));
    ctx.dispatch_over(p, ctx.texture("mask"));
    return {};
  }

 private:
  penumbra::gl::Sampler bilinear_{penumbra::gl::Sampler::Filter::linear, penumbra::gl::Sampler::Wrap::clamp};
};

}  // namespace

penumbra::exec::PassType moments_pass_type() {
  return penumbra::passes::light_view_pass_type(
      {.type_name = "msm_moments",
       .description = "MSM: four optimised moments of the casters' light depth (raster)",
       .fragment_shader = "msm/msm_moments.frag.glsl",
       .colour_targets = {{.slot = "moments", .formats = {Format::RGBA16, Format::RGBA32F},
                           .clear = optimised_moments(1.0f)}},
       .set_uniforms = [](PassContext&, const penumbra::gl::Program& program) {
         program.set("u_to_optimised", kToOptimised);
         program.set("u_optimised_offset", kOptimisedOffset);
       }});
}

penumbra::exec::PassType mask_pass_type() {
  return penumbra::exec::PassDeclBuilder("msm_mask")
      .describe("MSM: Hamburger 4MSM reconstruction of the receiver's shadow from filtered moments (compute)")
      .sampled("depth", {Format::R32F})
      .sampled("normal", {Format::RG16})
      .sampled("moments", {Format::RGBA16, Format::RGBA32F})
      .sampled("moments_wide", {Format::RGBA16, Format::RGBA32F}, false)
      .image_out("mask", {Format::R16F})
      .same_size({"depth", "mask"})
      .same_size({"moments", "moments_wide"})
      .real("moment_bias", 6e-5, 0.0, 0.01, "", "alpha: moments pulled towards (0.5, ...) against rounding (paper, 16-bit)")
      .real("depth_bias", 0.0, 0.0, 0.05, "window depth", "subtracted from the receiver's light depth (acne)")
      .real("narrow_height", 0.4, 0.0, 2.0, "of the scene's height along the light",
            "The moments' Gaussian is the light's penumbra of an edge this high above its receiver "
            "(separable_filter's penumbra_height)")
      .real("wide_height", 1.0, 0.0, 2.0, "of the scene's height along the light",
            "The same for moments_wide (contact hardening)")
      .build<MaskPass>();
}

void register_technique(penumbra::technique::TechniqueRegistry& registry) {
  registry.add({.name = "msm",
                .graph_file = "msm/msm.json",
                .register_passes = [](penumbra::exec::PassLibrary& library) {
                  library.add(moments_pass_type());
                  library.add(mask_pass_type());
                }});
}

}  // namespace msm
