// The tile list of the multi-pass blur (multipass_blur_pass.cpp): the tiles with D > 0, and per
// tile how many passes change it (shaders/blur_tiles.comp.glsl). Not in the paper: the blur is
// defined per pixel (Cherry & Kooima 3.1), and pixels with D = 0 never change, so passes after
// the first need only run where D > 0 (issue: work only where the penumbra is).
#include <glad/gl.h>

#include "passes/shadow_tiles/tiled_dispatch.h"
#include "techniques/mpg/passes/mpg_pass_common.h"
#include "techniques/mpg/passes/mpg_pass_types.h"

namespace penumbra::mpg {
namespace {

class BlurTilesPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const int tile = ctx.integer("tile_size");
    if (Status grid = passes::check_tile_grid(ctx, "tile_passes", "input", tile); !grid) return grid;
    gl::ShaderProgram& p = ctx.program({.compute = std::string(kShaderDir) + "blur_tiles.comp.glsl",
                                        .defines = {{"SCREEN_TILE", std::to_string(tile)}}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_distance_map", "input");
    ctx.bind_image(0, "tile_passes", GL_WRITE_ONLY);
    ctx.reset_tile_list("tiles");
    ctx.bind_tile_list(passes::kScreenTileListBinding, "tiles");
    const gl::Texture& input = ctx.texture("input");
    ctx.dispatch_tiles(p, input.width(), input.height(), tile);
    return {};
  }
};

}  // namespace

exec::PassType blur_tiles_pass_type() {
  return exec::PassDeclBuilder("mpg_blur_tiles")
      .describe("mpg, before pass 4 (multi-pass): lists the screen tiles with D > 0 and writes per tile the number "
                "of blur passes that change it (ceil of its largest D); later passes run over the list only")
      .sampled("input", {graph::Format::RGBA16F})
      .tile_list_out("tiles")
      .image_out("tile_passes", {graph::Format::R16F})
      .integer("tile_size", 16, 8, 16, "pixels", "Screen tile edge of the list")
      .step(8)
      .build<BlurTilesPass>();
}

}  // namespace penumbra::mpg
