#include "vsm_technique.h"

#include "exec/pass_decl_builder.h"
#include "passes/common/shadow_uniforms.h"

namespace vsm {
namespace {

using penumbra::Status;
using penumbra::exec::PassContext;
using penumbra::graph::Format;

// Shader paths are relative to the plugin directory, a shader root once the plugin is loaded.
class MomentsPass final : public penumbra::exec::PassImpl {
 public:
  Status execute(PassContext& ctx) override {
    penumbra::gl::ShaderProgram& p = ctx.program({.compute = "vsm/vsm_moments.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map");
    ctx.bind_image(0, "moments", GL_WRITE_ONLY);
    if (penumbra::Status s = penumbra::passes::set_shadow_uniforms(p.program(), ctx.frame()); !s) return s;
    p.program().set("u_radius", static_cast<int>(ctx.integer("blur_radius")));
    ctx.dispatch_over(p, ctx.texture("moments"));
    return {};
  }
};

class MaskPass final : public penumbra::exec::PassImpl {
 public:
  Status execute(PassContext& ctx) override {
    penumbra::gl::ShaderProgram& p = ctx.program({.compute = "vsm/vsm_mask.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_moments", "moments");
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    if (penumbra::Status s = penumbra::passes::set_shadow_uniforms(p.program(), ctx.frame()); !s) return s;
    p.program().set("u_min_variance", ctx.real("min_variance"));
    p.program().set("u_bleeding", ctx.real("light_bleeding"));
    ctx.dispatch_over(p, ctx.texture("mask"));
    return {};
  }
};

}  // namespace

penumbra::exec::PassType moments_pass_type() {
  return penumbra::exec::PassDeclBuilder("vsm_moments")
      .describe("VSM: box-filtered light distance and its square from a shadow map (compute)")
      .sampled("shadow_map", {Format::DEPTH32F})
      .image_out("moments", {Format::RG32F})
      .same_size({"shadow_map", "moments"})
      .integer("blur_radius", 2, 0, 8, "texels", "box filter radius over the moments: (2r+1)^2 taps")
      .build<MomentsPass>();
}

penumbra::exec::PassType mask_pass_type() {
  return penumbra::exec::PassDeclBuilder("vsm_mask")
      .describe("VSM: Chebyshev upper bound of the receiver's visibility (compute)")
      .sampled("depth", {Format::R32F})
      .sampled("moments", {Format::RG32F})
      .image_out("mask", {Format::R16F})
      .same_size({"depth", "mask"})
      .real("min_variance", 1e-4, 0.0, 1.0, "world units^2", "variance floor (acne on flat receivers)")
      .real("light_bleeding", 0.2, 0.0, 0.95, "", "visibility below this is cut to 0 and the rest rescaled")
      .build<MaskPass>();
}

void register_technique(penumbra::technique::TechniqueRegistry& registry) {
  registry.add({.name = "vsm",
                .graph_file = "vsm/vsm.json",
                .register_passes = [](penumbra::exec::PassLibrary& library) {
                  library.add(moments_pass_type());
                  library.add(mask_pass_type());
                }});
}

}  // namespace vsm
