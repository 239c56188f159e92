// Tile lists (graph/resources.h): sized by their tile grid, tile edges checked, barriers before
// the pass that dispatches over one, validation of a list nobody fills or a plain buffer where a
// list belongs, and the measured traffic of a pass that ran over part of its list.
// small_settings(): screen 256x128 = 32768 px.
#include <gtest/gtest.h>

#include "graph/graph_json.h"
#include "test_registry.h"

namespace penumbra::graph {
namespace {

using namespace testing;

// depth prepass -> tile_list_fill (appends tiles) -> tiled_filter (one work group per tile).
GraphDesc tiled_chain(SizeExpr tiles, bool with_writer = true) {
  GraphBuilder b("tiled");
  if (!tiles.divisor_reference.empty())
    b.parameter({.name = "tile", .type = ParamType::integer, .default_value = 16, .min = 1, .max = 64,
                 .description = "Tile edge", .structural = true});
  auto scene = b.import("scene"), camera = b.import("camera");
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  auto mask = b.texture("mask", Format::R16F, SizeExpr::screen());
  auto list = b.tile_list("penumbra_tiles", std::move(tiles));
  b.pass("depth_prepass", "prepass").read("scene", scene).read("camera", camera).write("depth", depth);
  if (with_writer) b.pass("tile_list_fill", "classify").read("depth", depth).write("tiles", list);
  b.pass("tiled_filter", "filter").read("depth", depth).read("tiles", list).write("mask", mask);
  b.output(mask);
  return b.build();
}

Checked<CompiledPlan> compile_at(const GraphDesc& g, CompileSettings settings, int tile_parameter = 16) {
  ParameterSet params(g.parameters);
  if (!g.parameters.empty())
    if (Status set = params.set("tile", tile_parameter); !set) ADD_FAILURE() << set.error().message;
  return compile(g, generic_registry(), params, settings);
}

std::uint64_t list_bytes(const CompiledPlan& plan) {
  for (const PhysicalResource& r : plan.physical)
    if (r.kind == ResourceKind::buffer) return r.bytes;
  return 0;
}

TEST(TileList, HoldsAHeaderAndOneEntryPerTileOfItsGridRoundedUp) {
  auto plan = compile_graph(tiled_chain(SizeExpr::screen(8)));
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  EXPECT_EQ(list_bytes(*plan), 16u + 4u * (256 / 8) * (128 / 8));
  // 250 x 100 in 8-pixel tiles: 32 x 13, the border's partial tiles included.
  auto odd = compile_at(tiled_chain(SizeExpr::screen(8)), {250, 100, 512});
  ASSERT_TRUE(odd) << all_messages(odd.errors());
  EXPECT_EQ(list_bytes(*odd), 16u + 4u * 32 * 13);
  // The edge from a structural parameter: 32-pixel tiles, 8 x 4.
  auto by_parameter = compile_at(tiled_chain(SizeExpr::screen_by("tile")), small_settings(), 32);
  ASSERT_TRUE(by_parameter) << all_messages(by_parameter.errors());
  EXPECT_EQ(list_bytes(*by_parameter), 16u + 4u * 8 * 4);
}

TEST(TileList, TileEdgeIsAPowerOfTwoFrom4To32) {
  for (int edge : {2, 6, 12, 64}) {
    auto plan = compile_graph(tiled_chain(SizeExpr::screen(edge)));
    ASSERT_FALSE(plan) << edge;
    EXPECT_TRUE(has_code(plan.errors(), GraphErrorCode::wrong_json_type)) << all_messages(plan.errors());
    EXPECT_NE(all_messages(plan.errors()).find("tile edge " + std::to_string(edge) + " must be a power of two in 4..32"),
              std::string::npos)
        << all_messages(plan.errors());
  }
  for (int edge : {4, 8, 16, 32}) EXPECT_TRUE(compile_graph(tiled_chain(SizeExpr::screen(edge)))) << edge;
  // From a parameter: the value the user set is named with the parameter.
  auto plan = compile_at(tiled_chain(SizeExpr::screen_by("tile")), small_settings(), 12);
  ASSERT_FALSE(plan);
  EXPECT_TRUE(has_code(plan.errors(), GraphErrorCode::param_out_of_range)) << all_messages(plan.errors());
  EXPECT_NE(all_messages(plan.errors()).find("tile edge 12 ('$tile')"), std::string::npos) << all_messages(plan.errors());
}

TEST(TileList, ThePassOverTheListWaitsForItsArgumentsAndEntries) {
  auto plan = compile_graph(tiled_chain(SizeExpr::screen(8)));
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  const PlannedPass& filter = plan->passes.at(static_cast<size_t>(position_of(*plan, "filter")));
  EXPECT_EQ(filter.barriers & (barrier_command | barrier_storage_buffer), barrier_command | barrier_storage_buffer)
      << barrier_bits_to_string(filter.barriers);
  ASSERT_NE(dispatch_tile_list(filter), nullptr);
  EXPECT_EQ(dispatch_tile_list(filter)->resource, "penumbra_tiles");
  const PlannedPass& classify = plan->passes.at(static_cast<size_t>(position_of(*plan, "classify")));
  EXPECT_EQ(dispatch_tile_list(classify), nullptr);  // it writes the list, it does not dispatch over it
  EXPECT_LT(position_of(*plan, "classify"), position_of(*plan, "filter"));
}

TEST(TileList, DispatchOverAListNobodyFillsNamesThePass) {
  auto plan = compile_graph(tiled_chain(SizeExpr::screen(8), /*with_writer=*/false));
  ASSERT_FALSE(plan);
  EXPECT_TRUE(has_code(plan.errors(), GraphErrorCode::read_without_producer)) << all_messages(plan.errors());
  const std::string messages = all_messages(plan.errors());
  EXPECT_NE(messages.find("filter"), std::string::npos) << messages;
  EXPECT_NE(messages.find("penumbra_tiles"), std::string::npos) << messages;
}

TEST(TileList, APlainBufferIsNoTileList) {
  GraphBuilder b("raw");
  auto scene = b.import("scene"), camera = b.import("camera");
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  auto mask = b.texture("mask", Format::R16F, SizeExpr::screen());
  auto raw = b.buffer("raw", 4096);
  b.pass("depth_prepass", "prepass").read("scene", scene).read("camera", camera).write("depth", depth);
  b.pass("tile_list_fill", "classify").read("depth", depth).write("tiles", raw);
  b.pass("tiled_filter", "filter").read("depth", depth).read("tiles", raw).write("mask", mask);
  b.output(mask);
  auto plan = compile_graph(b.build());
  ASSERT_FALSE(plan);
  EXPECT_TRUE(has_code(plan.errors(), GraphErrorCode::format_not_accepted)) << all_messages(plan.errors());
  EXPECT_NE(all_messages(plan.errors()).find("slot takes a tile list"), std::string::npos) << all_messages(plan.errors());
}

TEST(TileList, MeasuredTrafficCountsTheShareOfTilesDispatched) {
  auto plan = compile_graph(tiled_chain(SizeExpr::screen(8)));
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  const PlannedPass& filter = plan->passes.at(static_cast<size_t>(position_of(*plan, "filter")));
  const std::uint64_t depth = 256u * 128 * 4, mask = 256u * 128 * 2, list = list_bytes(*plan);
  EXPECT_EQ(filter.traffic.read_bytes, depth + list);  // the plan: every tile
  EXPECT_EQ(filter.traffic.written_bytes, mask);
  const PassTraffic quarter = pass_traffic(*plan, filter, 0.25);
  EXPECT_EQ(quarter.read_bytes, depth / 4 + list / 4);
  EXPECT_EQ(quarter.written_bytes, mask / 4);
  const PassTraffic all = pass_traffic(*plan, filter, 1.0);
  EXPECT_EQ(all.total(), filter.traffic.total());
  // A pass over no tile list is counted whole whatever fraction is given.
  const PlannedPass& classify = plan->passes.at(static_cast<size_t>(position_of(*plan, "classify")));
  EXPECT_EQ(pass_traffic(*plan, classify, 0.25).total(), classify.traffic.total());
}

// A list over the shadow map (shadow/8) scales what the shadow map's area holds, not the screen's.
TEST(TileList, MeasuredTrafficScalesTheTexturesOfTheListsOwnArea) {
  GraphBuilder b("shadow_tiled");
  auto scene = b.import("scene"), camera = b.import("camera");
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  auto map = b.texture("map", Format::R16F, SizeExpr::shadow());
  auto list = b.tile_list("map_tiles", SizeExpr::shadow(8));
  b.pass("depth_prepass", "prepass").read("scene", scene).read("camera", camera).write("depth", depth);
  b.pass("tile_list_fill", "classify").read("depth", depth).write("tiles", list);
  b.pass("tiled_filter", "filter").read("depth", depth).read("tiles", list).write("mask", map);
  b.output(map);
  auto plan = compile_at(b.build(), {256, 128, 512});
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  const PlannedPass& filter = plan->passes.at(static_cast<size_t>(position_of(*plan, "filter")));
  const std::uint64_t screen_depth = 256u * 128 * 4, shadow_texels = 512u * 512 * 2, bytes = list_bytes(*plan);
  const PassTraffic half = pass_traffic(*plan, filter, 0.5);
  EXPECT_EQ(half.read_bytes, screen_depth + bytes / 2);  // the screen's depth is read whole
  EXPECT_EQ(half.written_bytes, shadow_texels / 2);        // the shadow-sized output only where listed
}

TEST(TileList, JsonDeclaresItWithTiles) {
  auto graph = parse_graph_json(R"({"name": "t", "resources": {
      "list": {"kind": "buffer", "tiles": "screen/16"}}, "passes": []})");
  ASSERT_TRUE(graph) << all_messages(graph.errors());
  ASSERT_EQ(graph->resources.size(), 1u);
  EXPECT_TRUE(graph->resources[0].tile_list);
  EXPECT_EQ(graph->resources[0].size.to_string(), "screen/16");
  for (const char* bad : {R"({"kind": "buffer", "tiles": "64x64"})", R"({"kind": "buffer", "tiles": "screen/8", "bytes": 64})",
                          R"({"kind": "buffer", "tiles": 8})"}) {
    auto g = parse_graph_json(std::string(R"({"name": "t", "resources": {"list": )") + bad + R"(}, "passes": []})");
    ASSERT_FALSE(g) << bad;
    EXPECT_TRUE(has_code(g.errors(), GraphErrorCode::wrong_json_type)) << bad << ": " << all_messages(g.errors());
  }
}

}  // namespace
}  // namespace penumbra::graph
