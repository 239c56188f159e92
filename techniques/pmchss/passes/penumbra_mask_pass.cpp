// Penumbra mask pass (Sterna 2018, section 2.2): the blocker search at screen/4 or screen/2.
#include "exec/pass_decl_builder.h"
#include "gl/texture.h"
#include "techniques/pmchss/passes/pmchss_pass_common.h"
#include "techniques/pmchss/passes/pmchss_pass_types.h"

namespace penumbra::pmchss {
namespace {

using graph::Format;

class PenumbraMaskPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::Texture& shadow = ctx.texture("shadow_map");
    if (Status s = check_search_covers_texel(ctx, shadow.width()); !s) return s;
    gl::Texture& mask = ctx.texture("mask");
    bool blocker_depth = ctx.enumeration("output") == "blocker_depth";
    gl::ShaderProgram& p = ctx.program(
        {.compute = "techniques/pmchss/shaders/penumbra_mask.comp.glsl",
         .defines = {{"BLOCKER_SAMPLES", std::to_string(ctx.integer("blocker_samples"))},
                     {"FILTER_SAMPLES", "16"},
                     mapping_define(ctx),
                     {blocker_depth ? "OUTPUT_BLOCKER_DEPTH" : "OUTPUT_PENUMBRA", "1"}}});
    if (!p.valid()) return *p.last_error();
    if (nearest_.id() == 0) nearest_ = gl::Sampler(gl::Sampler::Filter::nearest, gl::Sampler::Wrap::clamp);
    ctx.bind_sampled(p, "u_position", "position");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", nearest_.id());
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    set_pmchss_uniforms(p.program(), ctx);
    p.program().set("u_default_one", ctx.boolean("default_one") ? 1 : 0);
    ctx.dispatch_over(p, mask.width(), mask.height());
    return {};
  }

 private:
  gl::Sampler nearest_;
};

}  // namespace

exec::PassType penumbra_mask_pass_type() {
  exec::PassDeclBuilder b("pmchss_penumbra_mask");
  b.describe("pmchss penumbra mask: reduced-resolution blocker search (Sterna 2018, 2.2)")
      .sampled("position", {Format::RGBA32F})
      .sampled("shadow_map", {Format::DEPTH32F})
      .imported("light", false)
      .image_out("mask", {Format::R16F});
  for (graph::ParamDesc& d : penumbra_params()) b.param(std::move(d));
  return b.param(int_param("blocker_samples", 32, 4, 64, "", "Blocker search taps"))
      .param(bool_param("default_one", false, "Write 1 where no blocker is found"))
      .param(enum_param("output", "penumbra", {"penumbra", "blocker_depth"},
                        "What to write: penumbra, or mean blocker window depth (debug)"))
      .build<PenumbraMaskPass>();
}

}  // namespace penumbra::pmchss
