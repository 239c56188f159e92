#include "passes/shadow_tiles/shadow_tiles_passes.h"

#include <algorithm>
#include <optional>
#include <string>

#include "exec/pass_decl_builder.h"
#include "passes/common/shadow_uniforms.h"
#include "passes/shadow_tiles/tiled_dispatch.h"

namespace penumbra::passes {
namespace {

using graph::Format;

class ShadowPlanesPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "passes/shadow_tiles/shadow_planes.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    if (!raw_) raw_.emplace(gl::Sampler::Filter::nearest, gl::Sampler::Wrap::clamp, false);
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", raw_->id());
    ctx.bind_image(0, "planes", GL_WRITE_ONLY);
    const gl::Texture& planes = ctx.texture("planes");
    // The work group's height is the invocations that share a block (shadow_planes.comp.glsl).
    ctx.dispatch_over(p, planes.width(), planes.height() * p.program().local_size().y);
    return {};
  }

 private:
  std::optional<gl::Sampler> raw_;
};

class ShadowTilesPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const int tile = ctx.integer("tile_size");
    // The class texture must cut the screen into the tiles this pass runs over.
    if (Status grid = check_tile_grid(ctx, "depth", tile); !grid) return grid;
    const gl::Texture& depth = ctx.texture("depth");
    gl::ShaderProgram& p = ctx.program({.compute = "passes/shadow_tiles/shadow_tiles.comp.glsl",
                                        .defines = {{"SCREEN_TILE", std::to_string(tile)}}});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_planes", "planes");
    ctx.bind_image(0, "tile_class", GL_WRITE_ONLY);
    ctx.reset_tile_list("tiles");
    ctx.bind_tile_list(kScreenTileListBinding, "tiles");
    if (Status s = set_shadow_uniforms(p.program(), ctx.frame(), SixFaces::read); !s) return s;
    const float texel = 1.0f / static_cast<float>(ctx.frame().shadow_size);
    // The largest tap offset of the filters this classifies for (shadow_tiles.comp.glsl).
    const float box_reach = ctx.integer("filter_box_size") > 0 ? 0.5f * float(ctx.integer("filter_box_size") + 1) : 0.0f;
    const float reach = 0.5f * std::max(ctx.real("search_width_uv"), ctx.real("filter_width_uv")) +
                        std::max(box_reach, ctx.real("filter_radius_texels")) * texel;
    const gl::Program& prog = p.program();
    prog.set("u_reach_uv", reach);
    prog.set("u_depth_bias", ctx.real("depth_bias"));
    ctx.dispatch_tiles(p, depth.width(), depth.height(), tile);
    return {};
  }
};

}  // namespace

exec::PassType shadow_planes_pass_type() {
  exec::PassDeclBuilder b("shadow_planes");
  b.describe("The shadow map as a fitted plane and residual depth range per block, for the tile classifier (compute)")
      .sampled("shadow_map", {Format::DEPTH32F})
      .image_out("planes", {Format::RGBA32F});
  return b.build<ShadowPlanesPass>();
}

exec::PassType shadow_tiles_pass_type() {
  exec::PassDeclBuilder b("shadow_tiles");
  b.describe("Classifies each screen tile lit, umbra or penumbra for the filters' taps and lists the penumbra tiles "
             "(compute)")
      .sampled("depth", {Format::R32F})
      .sampled("normal", {Format::RG16})
      .imported("light", false)
      .sampled("planes", {Format::RGBA32F})
      .image_out("tile_class", {Format::R8})
      .tile_list_out("tiles")
      .integer("tile_size", 16, 4, 32, "pixels", "Screen tile edge (the tile list's, a power of two)")
      .real("search_width_uv", 0.0, 0.0, 1.0, "shadow-map UV", "Widest blocker-search region the filters use")
      .real("filter_width_uv", 0.0, 0.0, 1.0, "shadow-map UV", "Widest filter kernel the filters use")
      .integer("filter_box_size", 0, 0, 15, "texels", "Width N of an N x N box of one-texel-apart taps (0: none)")
      .real("filter_radius_texels", 0.0, 0.0, 64.0, "texels", "Radius of a fixed kernel in texels (0: none)")
      .real("depth_bias", 0.0002, 0.0, 0.05, "window depth", "The filters' constant bias (their depth_bias)");
  return b.build<ShadowTilesPass>();
}

}  // namespace penumbra::passes
