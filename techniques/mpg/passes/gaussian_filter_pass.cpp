// Pass 4, single-pass Gaussian alteration of Cherry & Kooima (section 3.1): S filtered by a
// Gaussian of size D, sigma = size / 3; separable, one axis per dispatch.
#include <optional>

#include <glad/gl.h>

#include "techniques/mpg/passes/mpg_pass_common.h"
#include "techniques/mpg/passes/mpg_pass_types.h"

namespace penumbra::mpg {
namespace {

class GaussianFilterPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program(
        {.compute = std::string(kShaderDir) + "gaussian_filter.comp.glsl", .defines = {axis_define(ctx)}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_distance_map", "input", linear_sampler(linear_));
    ctx.bind_sampled(p, "u_kernel_shape", "kernel_shape");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    p.program().set("u_max_kernel", static_cast<float>(ctx.integer("max_kernel")));
    set_depth_aware_uniforms(p.program(), ctx);
    ctx.dispatch_over(p, ctx.texture("output"));
    return {};
  }

 private:
  std::optional<gl::Sampler> linear_;  // bilinear taps at fractional offsets
};

}  // namespace

exec::PassType gaussian_filter_pass_type() {
  exec::PassDeclBuilder b = distance_map_filter(
      "mpg_gaussian_filter",
      "mpg pass 4, single-pass Gaussian: S filtered by a Gaussian of size D, one axis (Cherry & Kooima 3.1)");
  b.enumeration("axis", "x", {"x", "y"}, "Which axis of the separable Gaussian").required();
  add_max_kernel(b);
  add_depth_aware(b);
  add_kernel_shape(b);
  return b.build<GaussianFilterPass>();
}

}  // namespace penumbra::mpg
