// Pass 5 of Cherry & Kooima (section 3.2): the frame's shadow_mask = 1 - S.
#include <glad/gl.h>

#include "techniques/mpg/passes/mpg_pass_common.h"
#include "techniques/mpg/passes/mpg_pass_types.h"

namespace penumbra::mpg {
namespace {

using graph::Format;

class ResolveMaskPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = std::string(kShaderDir) + "resolve_mask.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_distance_map", "input");
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    ctx.dispatch_over(p, ctx.texture("mask"));
    return {};
  }
};

}  // namespace

exec::PassType resolve_mask_pass_type() {
  return exec::PassDeclBuilder("mpg_resolve_mask")
      .describe("mpg pass 5: shadow_mask = 1 - S from the filtered distance map (Cherry & Kooima 3.2)")
      .sampled("input", {Format::RGBA16F})
      .image_out("mask", {Format::R16F})
      .same_size({"input", "mask"})
      .build<ResolveMaskPass>();
}

}  // namespace penumbra::mpg
