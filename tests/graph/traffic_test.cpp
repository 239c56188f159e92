// The traffic model (engine/graph/traffic.cpp) on plans whose bytes are counted by hand:
// screen 256x128 = 32768 px, shadow map 512x512 = 262144 texels (small_settings()).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_registry.h"

namespace penumbra::graph {
namespace {

using namespace testing;

constexpr std::uint64_t kPixels = 256 * 128;
constexpr std::uint64_t kShadowTexels = 512 * 512;

const PlannedPass& pass_named(const CompiledPlan& plan, const std::string& name) {
  int i = position_of(plan, name);
  EXPECT_GE(i, 0) << name;
  return plan.passes.at(static_cast<size_t>(std::max(i, 0)));
}

// shadow map (depth attachment) -> filter (samples the map and the screen depth, stores the mask)
// -> smooth (image load/store of the mask in place, repeated); beside it `half`, a blocker search
// into a screen/2 R32F texture.
GraphDesc filter_chain(Format mask_format, int smooth_passes) {
  GraphBuilder b("traffic");
  auto scene = b.import("scene"), light = b.import("light"), camera = b.import("camera");
  auto sm = b.texture("shadow_map", Format::DEPTH32F, SizeExpr::shadow());
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  auto mask = b.texture("mask", mask_format, SizeExpr::screen());
  auto blocker = b.texture("blocker", Format::R32F, SizeExpr::screen(2));
  b.pass("shadow_map", "shadow_map").read("scene", scene).read("light", light).write("depth", sm);
  b.pass("depth_prepass", "prepass").read("scene", scene).read("camera", camera).write("depth", depth);
  b.pass("penumbra_filter", "filter").read("shadow_map", sm).read("depth", depth).write("mask", mask);
  b.pass("blocker_search", "half").read("shadow_map", sm).read("depth", depth).write("blocker", blocker);
  b.pass("blur_in_place", "smooth").read_write("image", mask).repeat(smooth_passes);
  b.output(mask);
  b.output(blocker);
  return b.build();
}

TEST(Traffic, SampledReadsAndImageStoresCountEachTextureOnceAtItsSize) {
  auto plan = compile_graph(filter_chain(Format::R16F, 1));
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  const PassTraffic& filter = pass_named(*plan, "filter").traffic;
  EXPECT_EQ(filter.read_bytes, kShadowTexels * 4 + kPixels * 4);  // DEPTH32F map + DEPTH32F screen depth
  EXPECT_EQ(filter.written_bytes, kPixels * 2);                   // R16F mask
  const PassTraffic& half = pass_named(*plan, "half").traffic;
  EXPECT_EQ(half.read_bytes, kShadowTexels * 4 + kPixels * 4);
  EXPECT_EQ(half.written_bytes, (128 * 64) * 4);  // R32F at screen/2
}

TEST(Traffic, DepthAttachmentIsWrittenAndReadByTheDepthTestImportsCountNothing) {
  auto plan = compile_graph(filter_chain(Format::R16F, 1));
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  const PassTraffic& map = pass_named(*plan, "shadow_map").traffic;
  EXPECT_EQ(map.read_bytes, kShadowTexels * 4);
  EXPECT_EQ(map.written_bytes, kShadowTexels * 4);
  const PassTraffic& prepass = pass_named(*plan, "prepass").traffic;
  EXPECT_EQ(prepass.read_bytes, kPixels * 4);  // scene and camera are imported: nothing
  EXPECT_EQ(prepass.written_bytes, kPixels * 4);
}

TEST(Traffic, ReadWriteImagesCountBothWaysAndEveryRepetitionCountsAgain) {
  auto plan = compile_graph(filter_chain(Format::RGBA16F, 3));
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  for (const char* name : {"smooth[0]", "smooth[1]", "smooth[2]"}) {
    const PassTraffic& t = pass_named(*plan, name).traffic;
    EXPECT_EQ(t.read_bytes, kPixels * 8) << name;  // RGBA16F
    EXPECT_EQ(t.written_bytes, kPixels * 8) << name;
  }
  // The format decides: the same chain with an R16F mask moves a quarter of the bytes.
  auto narrow = compile_graph(filter_chain(Format::R16F, 3));
  ASSERT_TRUE(narrow) << all_messages(narrow.errors());
  EXPECT_EQ(pass_named(*narrow, "smooth[1]").traffic.total() * 4, pass_named(*plan, "smooth[1]").traffic.total());
}

TEST(Traffic, StorageBuffersCountTheirBytes) {
  GraphBuilder b("tiles");
  auto scene = b.import("scene"), camera = b.import("camera"), light = b.import("light");
  auto sm = b.texture("shadow_map", Format::DEPTH32F, SizeExpr::shadow());
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  auto tiles = b.buffer("tiles", 4096);
  auto mask = b.texture("mask", Format::R8, SizeExpr::screen());
  b.pass("shadow_map", "shadow_map").read("scene", scene).read("light", light).write("depth", sm);
  b.pass("depth_prepass", "prepass").read("scene", scene).read("camera", camera).write("depth", depth);
  b.pass("tile_classify", "classify").read("depth", depth).write("tiles", tiles);
  b.pass("penumbra_filter", "filter").read("shadow_map", sm).read("depth", depth).read("tiles", tiles)
      .write("mask", mask);
  b.output(mask);
  auto plan = compile_graph(b.build());
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  EXPECT_EQ(pass_named(*plan, "classify").traffic.written_bytes, 4096u);
  EXPECT_EQ(pass_named(*plan, "classify").traffic.read_bytes, kPixels * 4);
  EXPECT_EQ(pass_named(*plan, "filter").traffic.read_bytes, kShadowTexels * 4 + kPixels * 4 + 4096);
  EXPECT_EQ(pass_named(*plan, "filter").traffic.written_bytes, kPixels * 1);
}

TEST(Traffic, TableJsonAndDotAgreeWithThePlan) {
  auto plan = compile_graph(filter_chain(Format::R16F, 2));
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  const std::string table = traffic_table(*plan);
  // filter: 1.048576 + 0.131072 MB read, 0.065536 MB written, (1179648 + 65536) / 32768 = 38 B/px.
  EXPECT_NE(table.find("filter"), std::string::npos) << table;
  EXPECT_NE(table.find("1.18       0.07    38.00"), std::string::npos) << table;
  EXPECT_NE(table.find("total"), std::string::npos) << table;

  auto json = nlohmann::json::parse(to_json(*plan));
  ASSERT_EQ(json["passes"].size(), plan->passes.size());
  std::uint64_t sum = 0;
  for (size_t i = 0; i < plan->passes.size(); ++i) {
    EXPECT_EQ(json["passes"][i]["name"], plan->passes[i].name);
    EXPECT_EQ(json["passes"][i]["traffic"]["read_bytes"].get<std::uint64_t>(), plan->passes[i].traffic.read_bytes);
    EXPECT_EQ(json["passes"][i]["traffic"]["written_bytes"].get<std::uint64_t>(), plan->passes[i].traffic.written_bytes);
    sum += plan->passes[i].traffic.total();
  }
  EXPECT_GT(sum, 0u);
  EXPECT_NE(to_dot(*plan).find("read 1.2 MB, wrote 0.1 MB"), std::string::npos);
}

}  // namespace
}  // namespace penumbra::graph
