// Compiler behaviour on small builder-made graphs: culling, ordering, versions, expansion,
// barriers, keep-alive, parameter references.
#include <gtest/gtest.h>

#include <algorithm>

#include "test_registry.h"

namespace penumbra::graph {
namespace {

using namespace testing;

// light_depth -> filter -> (blur N times, in=mask out=mask) ; plus an unread debug pass.
GraphBuilder pcss_like(int blur_passes = 2) {
  GraphBuilder b("pcss_like");
  b.parameter({.name = "blur_passes", .type = ParamType::integer, .default_value = blur_passes,
               .min = 1, .max = 8, .structural = true});
  b.parameter({.name = "use_blur", .type = ParamType::boolean, .default_value = true, .structural = true});
  b.parameter({.name = "radius", .type = ParamType::integer, .default_value = 3, .min = 1, .max = 16});
  auto scene = b.import("scene"), light = b.import("light"), camera = b.import("camera");
  auto sm = b.texture("shadow_map", Format::DEPTH32F, SizeExpr::shadow());
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  auto mask = b.texture("shadow_mask", Format::R16F, SizeExpr::screen());
  auto debug = b.texture("debug", Format::R16F, SizeExpr::screen());
  b.pass("shadow_map", "light_depth").read("scene", scene).read("light", light).write("depth", sm);
  b.pass("depth_prepass", "camera_depth").read("scene", scene).read("camera", camera).write("depth", depth);
  b.pass("penumbra_filter", "filter").read("shadow_map", sm).read("depth", depth).write("mask", mask);
  b.pass("blur", "debug_view").read("input", mask).write("output", debug).param("radius", "$radius");
  b.pass("blur", "blur").read("input", mask).write("output", mask)
      .param("radius", "$radius").repeat("$blur_passes").enabled("$use_blur");
  b.output(mask);
  return b;
}

TEST(GraphCulling, CulledPassNeverInOrderAndListed) {
  auto plan = compile_graph(pcss_like().build());
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  EXPECT_EQ(position_of(*plan, "debug_view"), -1);
  EXPECT_NE(std::find(plan->culled.begin(), plan->culled.end(), "debug_view"), plan->culled.end());
  for (const auto& p : plan->passes)
    EXPECT_EQ(std::find(plan->culled.begin(), plan->culled.end(), p.name), plan->culled.end());
  // Nothing the debug pass wrote is planned.
  EXPECT_EQ(plan->physical_for("debug"), -1);
}

TEST(GraphCulling, ChainFeedingOnlyCulledPassesIsCulledToo) {
  GraphBuilder b("chain");
  auto scene = b.import("scene"), light = b.import("light");
  auto sm = b.texture("sm", Format::DEPTH32F, SizeExpr::shadow());
  auto a = b.texture("a", Format::R16F, SizeExpr::screen());
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  b.pass("shadow_map", "unused_depth").read("scene", scene).read("light", light).write("depth", sm);
  b.pass("penumbra_filter", "unused_filter").read("shadow_map", sm).read("depth", depth).write("mask", a);
  b.pass("depth_prepass", "camera_depth").read("scene", scene).read("camera", scene).write("depth", depth);
  b.output(depth);
  // unused_filter reads depth (declared later) -> read with no producer; use an explicit version.
  GraphDesc g = b.build();
  g.passes[1].slots[1].version = 1;
  auto plan = compile_graph(g);
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  ASSERT_EQ(plan->passes.size(), 1u);
  EXPECT_EQ(plan->passes[0].name, "camera_depth");
  EXPECT_EQ(plan->culled, (std::vector<std::string>{"unused_depth", "unused_filter"}));
}

TEST(GraphCulling, SideEffectPassIsKept) {
  GraphBuilder b("present");
  auto out = b.import("output");
  auto scene = b.import("scene"), camera = b.import("camera");
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  b.pass("depth_prepass", "camera_depth").read("scene", scene).read("camera", camera).write("depth", depth);
  b.pass("composite", "present").read("mask", depth).write("target", out);
  auto plan = compile_graph(b.build());  // no outputs at all: composite is a side effect
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  EXPECT_EQ(plan->passes.size(), 2u);
  EXPECT_TRUE(plan->culled.empty());
}

TEST(GraphOrdering, IndependentPassesKeepDeclarationOrder) {
  auto plan = compile_graph(pcss_like().build());
  ASSERT_TRUE(plan);
  std::vector<std::string> names;
  for (const auto& p : plan->passes) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"light_depth", "camera_depth", "filter", "blur[0]", "blur[1]"}));
}

TEST(GraphOrdering, ExplicitForwardVersionMovesProducerFirst) {
  GraphBuilder b("forward");
  auto scene = b.import("scene"), light = b.import("light"), camera = b.import("camera");
  auto sm = b.texture("sm", Format::DEPTH32F, SizeExpr::shadow());
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  auto mask = b.texture("mask", Format::R8, SizeExpr::screen());
  b.pass("penumbra_filter", "filter").read("shadow_map", sm.at(1)).read("depth", depth.at(1)).write("mask", mask);
  b.pass("shadow_map", "light_depth").read("scene", scene).read("light", light).write("depth", sm);
  b.pass("depth_prepass", "camera_depth").read("scene", scene).read("camera", camera).write("depth", depth);
  b.output(mask);
  auto plan = compile_graph(b.build());
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  EXPECT_EQ(position_of(*plan, "light_depth"), 0);
  EXPECT_EQ(position_of(*plan, "camera_depth"), 1);
  EXPECT_EQ(position_of(*plan, "filter"), 2);
}

TEST(GraphVersions, PingPongIsRenamingWithTwoPhysicalTextures) {
  auto plan = compile_graph(pcss_like(3).build());
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  // blur[i] reads shadow_mask@(i+1) and writes @(i+2): iteration i reads what i-1 wrote.
  for (int i = 0; i < 3; ++i) {
    const auto& p = plan->passes[position_of(*plan, "blur[" + std::to_string(i) + "]")];
    const PlannedBinding* in = nullptr;
    const PlannedBinding* out = nullptr;
    for (const auto& b : p.bindings) (b.slot == "input" ? in : out) = &b;
    ASSERT_TRUE(in && out);
    EXPECT_EQ(in->read_version, i + 1);
    EXPECT_EQ(out->write_version, i + 2);
    EXPECT_NE(in->physical, out->physical) << "reading and writing one texture in a pass";
  }
  // Consecutive versions alternate between two textures.
  EXPECT_EQ(plan->physical_for("shadow_mask", 1), plan->physical_for("shadow_mask", 3));
  EXPECT_EQ(plan->physical_for("shadow_mask", 2), plan->physical_for("shadow_mask", 4));
  EXPECT_EQ(plan->physical_for("shadow_mask"), plan->physical_for("shadow_mask", 4));
}

// A ping-pong write lands in the texture of the version two back, even where the pool would hand
// out another free texture of the descriptor, and the readers of that version run first.
TEST(GraphVersions, PingPongWriteSharesTheTextureOfTheVersionTwoBack) {
  GraphBuilder b("tiled_ping_pong");
  auto scene = b.import("scene"), camera = b.import("camera");
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  auto mask = b.texture("mask", Format::R16F, SizeExpr::screen());
  auto spare = b.texture("spare", Format::R16F, SizeExpr::screen());  // same descriptor as mask
  auto late = b.texture("late_view", Format::R16F, SizeExpr::screen());
  auto view = b.texture("view", Format::R16F, SizeExpr::screen());
  b.pass("depth_prepass", "camera_depth").read("scene", scene).read("camera", camera).write("depth", depth);
  b.pass("penumbra_filter", "spare_filter").read("shadow_map", depth).read("depth", depth).write("mask", spare);
  b.pass("blur", "spare_view").read("input", spare).write("output", late);
  b.pass("penumbra_filter", "filter").read("shadow_map", depth).read("depth", depth).write("mask", mask);
  b.pass("tiled_blur", "blur").read("input", mask).write("output", mask).repeat(4);
  // Declared last, reads mask@2, which blur[2] overwrites in place: it must run before blur[2].
  b.pass("blur", "view_of_first").read("input", mask.at(2)).write("output", view);
  b.output(mask);
  b.output(late);
  b.output(view);
  auto plan = compile_graph(b.build());
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  for (int v = 3; v <= 5; ++v) EXPECT_EQ(plan->physical_for("mask", v), plan->physical_for("mask", v - 2)) << "@" << v;
  EXPECT_NE(plan->physical_for("mask", 1), plan->physical_for("mask", 2));
  EXPECT_LT(position_of(*plan, "view_of_first"), position_of(*plan, "blur[2]"));
  EXPECT_LT(position_of(*plan, "blur[1]"), position_of(*plan, "view_of_first"));
}

TEST(GraphVersions, ReadWriteStaysInOnePhysicalTexture) {
  GraphBuilder b("in_place");
  b.parameter({.name = "n", .type = ParamType::integer, .default_value = 4, .min = 1, .max = 64, .structural = true});
  auto scene = b.import("scene"), camera = b.import("camera");
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  auto mask = b.texture("mask", Format::R8, SizeExpr::screen());
  b.pass("depth_prepass", "camera_depth").read("scene", scene).read("camera", camera).write("depth", depth);
  b.pass("penumbra_filter", "filter").read("shadow_map", depth).read("depth", depth).write("mask", mask);
  b.pass("blur_in_place", "smooth").read_write("image", mask).repeat("$n");
  b.output(mask);
  auto plan = compile_graph(b.build());
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  ASSERT_EQ(plan->passes.size(), 6u);
  for (int v = 1; v <= 5; ++v) EXPECT_EQ(plan->physical_for("mask", v), plan->physical_for("mask", 1));
  const auto& last = plan->passes[5];
  EXPECT_EQ(last.name, "smooth[3]");
  EXPECT_EQ(last.bindings[0].read_version, 4);
  EXPECT_EQ(last.bindings[0].write_version, 5);
  // Each in-place iteration follows an image store: a shader_image_access barrier each time.
  for (int i = 3; i < 6; ++i) EXPECT_EQ(plan->passes[i].barriers, barrier_shader_image_access);
}

TEST(GraphExpansion, RepeatAndEnabledFollowParameters) {
  GraphDesc g = pcss_like().build();
  ParameterSet params(g.parameters);
  ASSERT_TRUE(params.set("blur_passes", 5));
  auto plan = compile(g, generic_registry(), params, small_settings());
  ASSERT_TRUE(plan);
  EXPECT_NE(position_of(*plan, "blur[4]"), -1);
  EXPECT_EQ(position_of(*plan, "blur[5]"), -1);
  EXPECT_EQ(plan->passes[position_of(*plan, "blur[4]")].iteration, 4);
  ASSERT_TRUE(params.set("use_blur", false));
  plan = compile(g, generic_registry(), params, small_settings());
  ASSERT_TRUE(plan);
  EXPECT_EQ(plan->disabled, std::vector<std::string>{"blur"});
  EXPECT_EQ(position_of(*plan, "blur[0]"), -1);
  EXPECT_EQ(plan->physical_for("shadow_mask"), plan->physical_for("shadow_mask", 1));
}

TEST(GraphExpansion, EnabledExpressions) {
  GraphBuilder b("conditions");
  b.parameter({.name = "a", .type = ParamType::boolean, .default_value = true, .structural = true});
  b.parameter({.name = "b", .type = ParamType::boolean, .default_value = false, .structural = true});
  b.parameter({.name = "variant", .type = ParamType::enumeration, .default_value = std::string("mask"),
               .structural = true, .options = {"mask", "debug"}});
  auto scene = b.import("scene"), camera = b.import("camera");
  auto out = b.import("output");
  const char* conditions[] = {"$a", "!$a", "$a && $b", "$a || $b", "$variant == \"mask\"",
                              "$variant != \"mask\"", "!($a && !$b)"};
  const bool expected[] = {true, false, false, true, true, false, false};
  for (int i = 0; i < 7; ++i) {
    auto d = b.texture("d" + std::to_string(i), Format::DEPTH32F, SizeExpr::screen());
    b.pass("depth_prepass", "p" + std::to_string(i)).read("scene", scene).read("camera", camera)
        .write("depth", d).enabled(conditions[i]);
    b.pass("composite", "c" + std::to_string(i)).read("mask", d).write("target", out)
        .enabled(conditions[i]);
  }
  auto plan = compile_graph(b.build());
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  for (int i = 0; i < 7; ++i)
    EXPECT_EQ(position_of(*plan, "p" + std::to_string(i)) >= 0, expected[i]) << conditions[i];
}

TEST(GraphBarriers, ImageStoreThenSampleNeedsTextureFetchAttachmentNeedsNone) {
  auto plan = compile_graph(pcss_like(1).build());
  ASSERT_TRUE(plan);
  // filter samples two depth attachments: no barrier.
  EXPECT_EQ(plan->passes[position_of(*plan, "filter")].barriers, barrier_none);
  // blur samples the mask filter wrote with image store.
  const auto& blur = plan->passes[position_of(*plan, "blur")];
  EXPECT_EQ(blur.barriers, barrier_texture_fetch);
  ASSERT_EQ(blur.barrier_reasons.size(), 1u);
  EXPECT_EQ(blur.barrier_reasons[0], "shadow_mask@1: texture_fetch");
}

TEST(GraphPlan, ParameterReferencesStayReferences) {
  auto plan = compile_graph(pcss_like(1).build());
  ASSERT_TRUE(plan);
  const auto& blur = plan->passes[position_of(*plan, "blur")];
  bool found_radius = false, found_sigma = false;
  for (const auto& p : blur.params) {
    if (p.name == "radius") {
      found_radius = true;
      EXPECT_EQ(p.reference, "radius");
      EXPECT_EQ(std::get<int>(p.value), 3);
    }
    if (p.name == "sigma") {  // not bound: the pass type's default, resolved
      found_sigma = true;
      EXPECT_TRUE(p.reference.empty());
      EXPECT_DOUBLE_EQ(std::get<double>(p.value), 2.0);
    }
  }
  EXPECT_TRUE(found_radius && found_sigma);
}

TEST(GraphPlan, KeepAliveExtendsLifetimeAndPreventsReuse) {
  CompileOptions keep;
  keep.keep_alive = {"shadow_mask"};
  auto plan = compile_graph(pcss_like(2).build(), keep);
  ASSERT_TRUE(plan);
  const int end = static_cast<int>(plan->passes.size());
  std::vector<int> mask_physical;
  for (const auto& v : plan->versions)
    if (v.name == "shadow_mask") {
      EXPECT_EQ(v.last_use, end) << v.label();
      mask_physical.push_back(v.physical);
    }
  std::sort(mask_physical.begin(), mask_physical.end());
  EXPECT_EQ(std::unique(mask_physical.begin(), mask_physical.end()), mask_physical.end())
      << "a kept-alive version shares its texture with a later one";
}

TEST(GraphPlan, TextAndDotExportsAreDeterministic) {
  auto a = compile_graph(pcss_like().build());
  auto b = compile_graph(pcss_like().build());
  ASSERT_TRUE(a && b);
  EXPECT_EQ(to_text(*a), to_text(*b));
  EXPECT_EQ(to_dot(*a), to_dot(*b));
  EXPECT_NE(to_dot(*a).find("digraph"), std::string::npos);
  EXPECT_NE(to_text(*a).find("memory naive"), std::string::npos);
}

}  // namespace
}  // namespace penumbra::graph
