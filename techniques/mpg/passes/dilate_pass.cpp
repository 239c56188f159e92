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
    const bool input_marks = ctx.bound("input_marks"), output_marks = ctx.bound("output_marks");
    const bool blur_list = ctx.bound("tiles");
    const bool y = ctx.enumeration("axis") == "y";
    if (output_marks && y)
      return make_error("pass '" + ctx.pass().name + "': output_marks (tiles with a non-zero row maximum) is "
                        "written by the x pass only");
    if (blur_list && (!y || !ctx.bound("tile_passes")))
      return make_error("pass '" + ctx.pass().name + "': the blur's tile list ('tiles' with 'tile_passes') is "
                        "written by the y pass only, and needs both slots bound");
    gl::ShaderProgram& p = ctx.program({.compute = std::string(kShaderDir) + "dilate.comp.glsl",
                                        .defines = {axis_define(ctx),
                                                    {"INPUT_MARKS", input_marks ? "1" : "0"},
                                                    {"OUTPUT_MARKS", output_marks ? "1" : "0"},
                                                    {"BLUR_LIST", blur_list ? "1" : "0"}}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_distance_map", "input");
    ctx.bind_sampled(p, "u_kernel_shape", "kernel_shape");
    ctx.bind_image(0, "output", GL_WRITE_ONLY);
    const int kernel = ctx.integer("dilation_kernel");
    const int radius = (kernel - 1) / 2;
    p.program().set("u_radius", radius);
    if (input_marks) {
      if (Status grid = passes::check_tile_grid(ctx, "input_marks", "output", kDTile); !grid) return grid;
      ctx.bind_sampled(p, "u_input_marks", "input_marks");
      // Farthest tap in pixels: a shaped axis stretches by at most sqrt(6) < 2.5 (dilate.comp.glsl).
      const int reach = static_cast<int>(std::ceil(2.5 * radius + 1.0));
      p.program().set("u_tile_reach", (reach + kDTile - 1) / kDTile);
    }
    if (blur_list) {
      if (Status grid = passes::check_tile_grid(ctx, "tile_passes", "output", kDTile); !grid) return grid;
      ctx.bind_image(2, "tile_passes", GL_WRITE_ONLY);
      ctx.reset_tile_list("tiles");
      ctx.bind_tile_list(passes::kScreenTileListBinding, "tiles");
    }
    if (output_marks) {
      if (Status grid = passes::check_tile_grid(ctx, "output_marks", "output", kDTile); !grid) return grid;
      ctx.bind_image(1, "output_marks", GL_WRITE_ONLY);
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
  // Tile marks (shaders/tile_marks.glsl): where this pass's input channel (D for x, x's row
  // maxima for y) may be non-zero, and, from the x pass, where its row maxima are.
  b.sampled("input_marks", {graph::Format::R8}, false).image_out("output_marks", {graph::Format::R8}, false);
  // The y pass sets D for the last time before a multi-pass blur: it may list the blur's tiles
  // (what mpg_blur_tiles does otherwise; shaders/blur_tile_list.glsl).
  b.tile_list_out("tiles", false).image_out("tile_passes", {graph::Format::R16F}, false);
  return b.build<DilatePass>();
}

}  // namespace penumbra::mpg
