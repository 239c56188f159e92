// Pass 3 of Cherry & Kooima (section 3.1): Gaussian dilation of D into lit pixels, the outer
// penumbra. Separable, one axis per pass (dilate.comp.glsl says why a dilation and not an average).
#include <cmath>

#include <glad/gl.h>

#include "passes/shadow_tiles/tiled_dispatch.h"
#include "techniques/mpg/passes/mpg_pass_common.h"
#include "techniques/mpg/passes/mpg_pass_types.h"

namespace penumbra::mpg {
namespace {

class DilatePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const bool skip = ctx.bound("d_tiles");
    gl::ShaderProgram& p = ctx.program({.compute = std::string(kShaderDir) + "dilate.comp.glsl",
                                        .defines = {axis_define(ctx), {"D_TILES", skip ? "1" : "0"}}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_distance_map", "input");
    ctx.bind_sampled(p, "u_kernel_shape", "kernel_shape");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    const int kernel = ctx.integer("dilation_kernel");
    const int radius = (kernel - 1) / 2;
    p.program().set("u_radius", radius);
    if (skip) {
      if (Status grid = passes::check_tile_grid(ctx, "d_tiles", "output", kDTile); !grid) return grid;
      ctx.bind_sampled(p, "u_d_tiles", "d_tiles");
      // Farthest tap in pixels (a shaped axis stretches by at most sqrt(6) < 2.5, dilate.comp.glsl);
      // the y pass reads the x pass's row maxima, so D reaches it from twice as far.
      const int reach = static_cast<int>(std::ceil(2.5 * radius + 1.0)) * (ctx.enumeration("axis") == "y" ? 2 : 1);
      p.program().set("u_tile_reach", (reach + kDTile - 1) / kDTile);
    }
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
  b.sampled("d_tiles", {graph::Format::R8}, false);
  return b.build<DilatePass>();
}

}  // namespace penumbra::mpg
