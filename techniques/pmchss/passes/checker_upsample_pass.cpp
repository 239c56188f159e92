// Checkerboard upsample (Sterna 2018, section 3): unpack the computed half of the pixels and
// fill the others from their four neighbours weighted by 1 / (eps + |delta linear depth|).
#include "exec/pass_decl_builder.h"
#include "gl/texture.h"
#include "techniques/pmchss/passes/pmchss_pass_common.h"
#include "techniques/pmchss/passes/pmchss_pass_types.h"

namespace penumbra::pmchss {
namespace {

using graph::Format;

class CheckerUpsamplePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/pmchss/shaders/checker_upsample.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_checker", "checker");
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    p.program().set("u_depth_epsilon", ctx.real("depth_epsilon"));
    gl::Texture& mask = ctx.texture("mask");
    ctx.dispatch_over(p, mask.width(), mask.height());
    return {};
  }
};

}  // namespace

exec::PassType checker_upsample_pass_type() {
  return exec::PassDeclBuilder("pmchss_checker_upsample")
      .describe("Checkerboard shadow mask -> full resolution, depth-aware (Sterna 2018, 3)")
      .sampled("checker", {Format::RG16F})
      .sampled("depth", {Format::R32F})
      .image_out("mask", {Format::R16F})
      .same_size({"depth", "mask"})
      .param(real_param("depth_epsilon", 0.001, 1e-6, 10.0, "world units",
                        "eps of the upsample weight 1 / (eps + |delta linear depth|)"))
      .build<CheckerUpsamplePass>();
}

}  // namespace penumbra::pmchss
