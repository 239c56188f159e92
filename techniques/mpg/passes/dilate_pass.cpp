// Pass 3 of Cherry & Kooima (section 3.1): Gaussian dilation of D into lit pixels, the outer
// penumbra. Separable, one axis per pass (dilate.comp.glsl says why a dilation and not an average).
#include <glad/gl.h>

#include "techniques/mpg/passes/mpg_pass_common.h"
#include "techniques/mpg/passes/mpg_pass_types.h"

namespace penumbra::mpg {
namespace {

class DilatePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p =
        ctx.program({.compute = std::string(kShaderDir) + "dilate.comp.glsl", .defines = {axis_define(ctx)}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_distance_map", "input");
    ctx.bind_sampled(p, "u_kernel_shape", "kernel_shape");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    const int kernel = ctx.integer("dilation_kernel");
    p.program().set("u_radius", (kernel - 1) / 2);
    p.program().set("u_kernel", static_cast<float>(kernel));
    set_depth_aware_uniforms(p.program(), ctx);
    ctx.dispatch_over(p, ctx.texture("output"));
    return {};
  }
};

}  // namespace

exec::PassType dilate_pass_type() {
  exec::PassDeclBuilder b = distance_map_filter(
      "mpg_dilate", "mpg pass 3: Gaussian dilation of D into lit pixels, one axis (Cherry & Kooima 3.1)");
  b.enumeration("axis", "x", {"x", "y"}, "Which axis of the separable dilation")
      .required()
      .integer("dilation_kernel", 9, 3, kMaxKernel, "pixels",
               "Pass 3's dilation kernel K, odd; Gaussian fall-off sigma = K / 3")
      .step(2);
  add_depth_aware(b);
  add_kernel_shape(b);
  return b.build<DilatePass>();
}

}  // namespace penumbra::mpg
