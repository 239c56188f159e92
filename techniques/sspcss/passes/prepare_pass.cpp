// Preparation (section 1): the hard shadow and the projected shadow map in screen space
// (shaders/prepare.comp.glsl).
#include <optional>

#include "exec/pass_decl_builder.h"
#include "passes/common/shadow_receiver_decl.h"
#include "passes/common/shadow_uniforms.h"
#include "techniques/sspcss/passes/sspcss_pass_common.h"
#include "techniques/sspcss/passes/sspcss_pass_types.h"

namespace penumbra::sspcss {
namespace {

using graph::Format;

class PreparePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/sspcss/shaders/prepare.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    if (!compare_) compare_.emplace(gl::Sampler::Filter::linear, gl::Sampler::Wrap::clamp, true);
    if (!raw_) raw_.emplace(gl::Sampler::Filter::nearest, gl::Sampler::Wrap::clamp, false);
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", raw_->id());
    ctx.bind_sampled(p, "u_shadow_cmp", "shadow_map", compare_->id());
    ctx.bind_image(0, "projected", GL_WRITE_ONLY);
    if (Status s = passes::set_shadow_uniforms(p.program(), ctx.frame(), passes::SixFaces::read); !s) return s;
    p.program().set("u_depth_bias", ctx.real("depth_bias"));
    set_screen_uniforms(p.program(), ctx.frame());
    p.program().set("u_view_inverse", glm::inverse(ctx.frame().view()));
    p.program().set("u_subpixel", ctx.boolean("subpixel_hard_shadow") ? 1 : 0);
    ctx.dispatch_over(p, ctx.texture("projected"));
    return {};
  }

 private:
  std::optional<gl::Sampler> compare_, raw_;
};

}  // namespace

exec::PassType prepare_pass_type() {
  return passes::shadow_receiver_pass(
             "sspcss_prepare",
             "SSPCSS preparation: hard visibility, projected shadow map (closest blocker's light "
             "distance), view depth, faces-away flag per pixel (compute)")
      .image_out("projected", {Format::RGBA16F})
      .same_size({"depth", "normal", "projected"})
      .real("depth_bias", 0.0002, 0.0, 0.05, "window depth",
            "Constant bias subtracted from the receiver-plane depth in the hard shadow's comparison")
      .boolean("subpixel_hard_shadow", true,
               "Hard shadow from 2x2 sub-pixel samples on the receiver plane (anti-aliased: shadows thinner than a "
               "pixel still reach the search and the filter); false = one sample at the pixel centre, 4x fewer "
               "shadow-map reads")
      .build<PreparePass>();
}

}  // namespace penumbra::sspcss
