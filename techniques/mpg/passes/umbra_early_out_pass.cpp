// Umbra early-out (Cherry & Kooima, section 5): D = 0 where the whole neighbourhood is shadowed.
// Separable: axis x writes each row's minimum of S to the distance map's scratch channel, axis y
// takes the column minimum of that (umbra_early_out.comp.glsl).
#include <glad/gl.h>

#include "techniques/mpg/passes/mpg_pass_common.h"
#include "techniques/mpg/passes/mpg_pass_types.h"

namespace penumbra::mpg {
namespace {

class UmbraEarlyOutPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const int neighbourhood = ctx.integer("umbra_neighbourhood"), max_kernel = ctx.integer("max_kernel");
    if (neighbourhood < max_kernel) {
      // Section 5: "examines a neighbor around each pixel, that is at least as big as the max
      // kernel size"; a smaller one would freeze pixels the very first blur reaches.
      return make_error("umbra_neighbourhood (" + std::to_string(neighbourhood) +
                        " pixels) must be at least max_kernel (" + std::to_string(max_kernel) +
                        " pixels): a smaller neighbourhood freezes pixels inside the blur's reach; raise "
                        "umbra_neighbourhood to " + std::to_string(max_kernel) +
                        " or more (larger leaves the inner penumbra more room), or turn umbra_early_out off");
    }
    gl::ShaderProgram& p = ctx.program(
        {.compute = std::string(kShaderDir) + "umbra_early_out.comp.glsl", .defines = {axis_define(ctx)}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_distance_map", "input");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    p.program().set("u_radius", (neighbourhood - 1) / 2);
    ctx.dispatch_over(p, ctx.texture("output"));
    return {};
  }
};

}  // namespace

exec::PassType umbra_early_out_pass_type() {
  exec::PassDeclBuilder b = distance_map_filter(
      "mpg_umbra_early_out", "mpg umbra early-out: D = 0 where the whole neighbourhood is shadowed, one axis "
                             "(Cherry & Kooima 5)");
  b.enumeration("axis", "x", {"x", "y"}, "Which axis of the separable test")
      .required()
      .integer("umbra_neighbourhood", 31, 3, kMaxKernel, "pixels",
               "Early-out neighbourhood N x N, odd, at least max_kernel (section 5: larger than the largest blur kernel)")
      .step(2);
  add_max_kernel(b);
  return b.build<UmbraEarlyOutPass>();
}

}  // namespace penumbra::mpg
