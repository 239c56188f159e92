// Min-filter variant, step 1 (Sterna 2018, section 2.3): min-downsample of the shadow map.
#include "exec/pass_decl_builder.h"
#include "gl/texture.h"
#include "techniques/pmchss/passes/pmchss_pass_common.h"
#include "techniques/pmchss/passes/pmchss_pass_types.h"

namespace penumbra::pmchss {
namespace {

using graph::Format;

class MinDownsamplePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::Texture& shadow = ctx.texture("shadow_map");
    gl::Texture& out = ctx.texture("min_depth");
    // The min map stands in for the blocker search, so the same smallest-size rule applies.
    if (Status s = check_search_covers_texel(ctx, shadow.width()); !s) return s;
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/pmchss/shaders/min_downsample.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map");
    ctx.bind_image(0, "min_depth", GL_WRITE_ONLY);
    ctx.dispatch_over(p, out.width(), out.height());
    return {};
  }
};

}  // namespace

exec::PassType min_downsample_pass_type() {
  return exec::PassDeclBuilder("pmchss_min_downsample")
      .describe("Min of each block of the shadow map, window depth (Sterna 2018, 2.3)")
      .sampled("shadow_map", {Format::DEPTH32F})
      .image_out("min_depth", {Format::R32F})
      .param(shadow_filter_max_size_param())
      .param(penumbra_kernel_scale_param())
      .build<MinDownsamplePass>();
}

}  // namespace penumbra::pmchss
