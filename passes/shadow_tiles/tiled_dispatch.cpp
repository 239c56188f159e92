#include "passes/shadow_tiles/tiled_dispatch.h"

#include "graph/resources.h"

namespace penumbra::passes {
void add_tile_list_slot(exec::PassDeclBuilder& builder) {
  builder.tile_list_in("tiles", false)
      .integer("tile_size", 16, 4, 32, "pixels", "Screen tile edge of the tile list, when tiled");
}

void add_tile_slots(exec::PassDeclBuilder& builder) {
  add_tile_list_slot(builder);
  builder.sampled("tile_class", {graph::Format::R8}, false);
}

bool tiled(const exec::PassContext& ctx) { return ctx.bound("tiles"); }

std::vector<std::pair<std::string, std::string>> tile_defines(const exec::PassContext& ctx,
                                                              std::vector<std::pair<std::string, std::string>> defines) {
  defines.emplace_back("SCREEN_TILED", tiled(ctx) ? "1" : "0");
  if (tiled(ctx)) defines.emplace_back("SCREEN_TILE", std::to_string(ctx.integer("tile_size")));
  return defines;
}

Status check_tile_grid(const exec::PassContext& ctx, std::string_view slot, int tile) {
  return check_tile_grid(ctx, "tile_class", slot, tile);
}

Status check_tile_grid(const exec::PassContext& ctx, std::string_view per_tile, std::string_view slot, int tile) {
  const gl::Texture& tiles = ctx.texture(per_tile);
  const gl::Texture& out = ctx.texture(slot);
  const int tiles_x = (out.width() + tile - 1) / tile, tiles_y = (out.height() + tile - 1) / tile;
  if (tiles.width() == tiles_x && tiles.height() == tiles_y) return {};
  return make_error("pass '" + ctx.pass().name + "': '" + std::string(per_tile) + "' is " +
                    std::to_string(tiles.width()) + "x" + std::to_string(tiles.height()) + " tiles, but '" +
                    std::string(slot) + "' (" + std::to_string(out.width()) + "x" + std::to_string(out.height()) +
                    ") in " + std::to_string(tile) + "-pixel tiles needs " + std::to_string(tiles_x) + "x" +
                    std::to_string(tiles_y) + " (the pass's tile_size, and '" + std::string(per_tile) +
                    "' sized \"tiles\": \"screen/" + std::to_string(tile) + "\")");
}

Status fill_constant_tiles(exec::PassContext& ctx, std::initializer_list<TileFill> fills) {
  if (!tiled(ctx)) return {};
  if (!ctx.bound("tile_class"))
    return make_error("pass '" + ctx.pass().name + "': slot 'tiles' is bound but 'tile_class' is not (bind both "
                      "to the shadow_tiles pass's outputs)");
  const int tile = ctx.integer("tile_size");
  for (const TileFill& fill : fills) {
    if (Status grid = check_tile_grid(ctx, fill.slot, tile); !grid) return grid;
    const gl::Texture& out = ctx.texture(fill.slot);
    gl::ShaderProgram& p = ctx.program(
        {.compute = "passes/shadow_tiles/tile_fill.comp.glsl",
         .defines = {{"MASK_FORMAT", graph::image_format_qualifier(out.format())}, {"SCREEN_TILE", std::to_string(tile)}}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_tile_class", "tile_class");
    ctx.bind_image(0, fill.slot, GL_WRITE_ONLY);
    p.program().set("u_lit_value", fill.lit);
    p.program().set("u_umbra_value", fill.umbra);
    ctx.dispatch_over(p, out.width(), out.height());
    if (ctx.binding_error()) return *ctx.binding_error();
  }
  return {};
}

void dispatch_screen(exec::PassContext& ctx, const gl::ShaderProgram& p, int width, int height) {
  if (!tiled(ctx)) {
    ctx.dispatch_over(p, width, height);
    return;
  }
  ctx.bind_tile_list(kScreenTileListBinding, "tiles");
  ctx.dispatch_over_tiles(p, "tiles");
}

}  // namespace penumbra::passes
