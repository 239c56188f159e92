#pragma once
// What a filter pass adds to run only over the penumbra tiles of the shared classifier
// (shadow_tiles_passes.h). Optional slots: bound, the pass fills its outputs' lit and umbra tiles
// with their constant values and runs its own shader over the listed tiles (one work group per
// tile: the shader includes screen_pass.glsl and takes its pixel from screen_pixel()); unbound,
// it runs over every pixel as before. Either way each output pixel gets the same value.
//
//   PassDeclBuilder b = ...; add_tile_slots(b);
//   execute(ctx):
//     fill_constant_tiles(ctx, {{"mask", lit, umbra}});   // before the pass binds its images
//     gl::ShaderProgram& p = ctx.program({.compute = ..., .defines = tile_defines(ctx)});
//     ... bind ...
//     dispatch_screen(ctx, p, width, height);
#include <glm/vec4.hpp>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exec/pass.h"
#include "exec/pass_decl_builder.h"

namespace penumbra::passes {

// The storage-buffer binding of the tile list in every screen pass (TILE_LIST_BINDING in
// screen_pass.glsl).
inline constexpr GLuint kScreenTileListBinding = 7;

// The optional slot "tiles" (a tile list) and the int parameter "tile_size" (pixels: the edge of
// the list's tiles, which is the shader's work group: SCREEN_TILE).
void add_tile_list_slot(exec::PassDeclBuilder& builder);

// add_tile_list_slot, for the classifier's penumbra tiles, and "tile_class" (its R8 texture),
// optional too.
void add_tile_slots(exec::PassDeclBuilder& builder);

bool tiled(const exec::PassContext& ctx);

// SCREEN_TILED (0/1) and SCREEN_TILE for screen_pass.glsl, appended to `defines`.
std::vector<std::pair<std::string, std::string>> tile_defines(
    const exec::PassContext& ctx, std::vector<std::pair<std::string, std::string>> defines = {});

// An output of the pass and what its lit and umbra tiles hold.
struct TileFill {
  std::string slot;
  glm::vec4 lit, umbra;
};

// Ok when `tile_class` holds one texel per tile of the texture in `slot` (tiles of `tile` pixels,
// the last row and column partial), else an error naming both and the sizes.
Status check_tile_grid(const exec::PassContext& ctx, std::string_view slot, int tile);
// The same for any per-tile texture: `per_tile` holds one texel per tile of `slot`.
Status check_tile_grid(const exec::PassContext& ctx, std::string_view per_tile, std::string_view slot, int tile);

// Writes each fill's values into the lit and umbra tiles of its output; nothing when untiled.
// Checks that the classifier's texture matches the screen and tile size.
Status fill_constant_tiles(exec::PassContext& ctx, std::initializer_list<TileFill> fills);

// Every pixel of width x height (untiled), or the listed tiles.
void dispatch_screen(exec::PassContext& ctx, const gl::ShaderProgram& p, int width, int height);

}  // namespace penumbra::passes
