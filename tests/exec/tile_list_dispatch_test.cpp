// A tile list end to end on the GL backend: one pass lists the 8 x 8 tiles a disk touches, the
// next runs one work group per listed tile (indirect dispatch, the count never read back by the
// CPU) and writes 1 there; the image is 1 exactly on those tiles, border tiles included, and the
// read-back bench uses says how many tiles ran.
#include <gtest/gtest.h>

#include <cmath>

#include "exec/executor.h"
#include "exec/pass_decl_builder.h"
#include "exec/tile_list_readback.h"
#include "graph/builder.h"
#include "graph/compiler.h"
#include "test_support/gl_context.h"
#include "test_support/read_back.h"

using namespace penumbra;
using namespace penumbra::graph;

namespace {

constexpr int kW = 44, kH = 21, kTile = 8;  // 6 x 3 tiles, the last column and row partial
constexpr float kCentreX = 30.0f, kCentreY = 9.0f, kRadius = 7.0f;

class TileMarkPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "tests/exec/shaders/tile_mark.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.reset_tile_list("tiles");
    ctx.bind_tile_list(0, "tiles");
    p.program().set("u_size", glm::ivec2(kW, kH));
    p.program().set("u_centre", glm::vec2(kCentreX, kCentreY));
    p.program().set("u_radius", kRadius);
    ctx.dispatch_over(p, kW, kH);
    return {};
  }
};

class TileFillPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "tests/exec/shaders/tile_fill.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.texture("out").clear(0.0f);  // tiles not listed stay 0
    ctx.bind_tile_list(0, "tiles");
    ctx.bind_image(0, "out", GL_WRITE_ONLY);
    ctx.dispatch_over_tiles(p, "tiles");
    return {};
  }
};

bool tile_touches_disk(int tx, int ty) {
  for (int y = ty * kTile; y < std::min(kH, (ty + 1) * kTile); ++y)
    for (int x = tx * kTile; x < std::min(kW, (tx + 1) * kTile); ++x)
      if (std::hypot(x + 0.5f - kCentreX, y + 0.5f - kCentreY) <= kRadius) return true;
  return false;
}

TEST(TileListDispatch, WorkGroupsRunOnExactlyTheListedTiles) {
  test::gl_context();
  exec::PassLibrary library;
  library.add(exec::PassDeclBuilder("test_tile_mark")
                  .describe("test: lists the tiles a disk touches")
                  .tile_list_out("tiles")
                  .build<TileMarkPass>());
  library.add(exec::PassDeclBuilder("test_tile_fill")
                  .describe("test: writes 1 on every listed tile")
                  .tile_list_in("tiles")
                  .image_out("out", {Format::R32F})
                  .build<TileFillPass>());
  GraphBuilder b("tiles");
  BufferHandle list = b.tile_list("disk_tiles", SizeExpr::screen(kTile));
  TextureHandle out = b.texture("out", Format::R32F, SizeExpr::screen());
  b.pass("test_tile_mark", "mark").write("tiles", list);
  b.pass("test_tile_fill", "fill").read("tiles", list).write("out", out);
  b.output(out);
  GraphDesc g = b.build();
  ParameterSet params(g.parameters);
  auto plan = compile(g, library.declarations(), params, {kW, kH, 8});
  ASSERT_TRUE(plan);
  exec::ShaderCache shaders;
  exec::TexturePool pool;
  exec::Executor executor(library, shaders, pool);
  ASSERT_TRUE(executor.set_plan(std::move(*plan)));
  for (int frame = 0; frame < 2; ++frame) {  // the writer empties the list every frame
    ASSERT_TRUE(executor.execute(params, exec::FrameInputs{}));
    const test::TextureImage image = test::read_texture(*executor.resource("out"));
    ASSERT_EQ(image.width, kW);
    int listed = 0, wrong = 0;
    for (int ty = 0; ty < (kH + kTile - 1) / kTile; ++ty)
      for (int tx = 0; tx < (kW + kTile - 1) / kTile; ++tx) {
        const bool expected = tile_touches_disk(tx, ty);
        listed += expected ? 1 : 0;
        // read_texture's rows run top down; GL's row y is kH - 1 - y there.
        for (int y = ty * kTile; y < std::min(kH, (ty + 1) * kTile); ++y)
          for (int x = tx * kTile; x < std::min(kW, (tx + 1) * kTile); ++x)
            wrong += image.at(x, kH - 1 - y, 0) != (expected ? 1.0f : 0.0f) ? 1 : 0;
      }
    EXPECT_EQ(wrong, 0) << "frame " << frame;
    ASSERT_GT(listed, 1);
    ASSERT_LT(listed, 18);
    const graph::PlannedPass& fill = executor.plan().passes.back();
    const std::optional<exec::TileListCount> count = exec::dispatched_tiles(executor, fill);
    ASSERT_TRUE(count.has_value());
    EXPECT_EQ(count->dispatched, static_cast<unsigned>(listed));
    EXPECT_EQ(count->capacity, 6u * 3u);
    EXPECT_FALSE(exec::dispatched_tiles(executor, executor.plan().passes.front()).has_value());
  }
}

}  // namespace
