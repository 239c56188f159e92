// Declarative parameter constraints: `step` (odd kernel sizes and the like) checked wherever a
// value is set, parsed from JSON, and required to agree between a pass type and the graph
// parameter bound to it; `applies` conditions parsed and checked against the graph's parameters.
#include <gtest/gtest.h>

#include "graph/graph_json.h"
#include "test_registry.h"

namespace penumbra::graph {
namespace {

using namespace testing;

ParamDesc odd_size() {
  ParamDesc d = int_param("box_size", 5, 1, 15, "texels", "Box width");
  d.step = 2;
  return d;
}

TEST(ParamStep, OnlyValuesOnTheGridAreAccepted) {
  ParameterSet p({odd_size()});
  EXPECT_TRUE(p.set("box_size", 7));
  EXPECT_TRUE(p.set("box_size", 15));
  Status even = p.set("box_size", 4);
  ASSERT_FALSE(even);
  EXPECT_NE(even.error().message.find("must be odd"), std::string::npos) << even.error().message;
  EXPECT_NE(even.error().message.find("1, 3, 5, ..., 15"), std::string::npos) << even.error().message;
  EXPECT_EQ(p.get_int("box_size"), 15);  // unchanged
  EXPECT_FALSE(p.set_from_string("box_size=8"));
  // The range still applies first.
  EXPECT_NE(p.set("box_size", 17).error().message.find("[1, 15]"), std::string::npos);
}

// A short grid is listed whole, never past its maximum (a tile edge of 8 or 16).
TEST(ParamStep, AFewValidValuesAreAllListed) {
  ParamDesc d = int_param("tile_size", 16, 8, 16, "pixels", "Tile edge");
  d.step = 8;
  ParameterSet p({d});
  EXPECT_TRUE(p.set("tile_size", 8));
  Status off = p.set("tile_size", 12);
  ASSERT_FALSE(off);
  EXPECT_NE(off.error().message.find("valid: 8, 16"), std::string::npos) << off.error().message;
  EXPECT_EQ(off.error().message.find("24"), std::string::npos) << off.error().message;
}

TEST(ParamStep, NearestValueRoundsHalfUpFromTheMinimum) {
  ParamDesc d = odd_size();
  EXPECT_EQ(nearest_step_value(d, 4), 5);
  EXPECT_EQ(nearest_step_value(d, 5), 5);
  EXPECT_EQ(nearest_step_value(d, 6), 7);
  EXPECT_EQ(nearest_step_value(d, 0), 1);
  EXPECT_EQ(nearest_step_value(d, -2), -1);
  d.min = 10;
  d.step = 5;
  EXPECT_EQ(nearest_step_value(d, 12), 10);
  EXPECT_EQ(nearest_step_value(d, 13), 15);
  EXPECT_NE(check_param_value(d, 12).error().message.find("10 + k * 5"), std::string::npos);
  d.step = 0;  // no step: every integer
  EXPECT_EQ(nearest_step_value(d, 12), 12);
  EXPECT_TRUE(check_param_value(d, 12));
}

TEST(ParamStep, JsonDeclaresItAndTheDefaultMustBeOnTheGrid) {
  auto ok = parse_graph_json(R"({"name": "x", "parameters": [
    {"name": "n", "type": "int", "default": 3, "min": 1, "max": 9, "step": 2}], "passes": []})", "s.json");
  ASSERT_TRUE(ok) << all_messages(ok.errors());
  EXPECT_EQ(ok->parameters[0].step, 2);
  auto even = parse_graph_json(R"({"name": "x", "parameters": [
    {"name": "n", "type": "int", "default": 4, "min": 1, "max": 9, "step": 2}], "passes": []})", "s.json");
  ASSERT_FALSE(even);
  EXPECT_EQ(even.errors()[0].where, "/parameters/0/default") << all_messages(even.errors());
  for (const char* bad : {R"("type": "float", "default": 1.0, "step": 2)", R"("type": "int", "default": 1, "step": 0)",
                          R"("type": "int", "default": 1, "step": 1.5)"}) {
    auto g = parse_graph_json(std::string(R"({"name": "x", "parameters": [{"name": "n", )") + bad + R"(}], "passes": []})",
                              "s.json");
    ASSERT_FALSE(g) << bad;
    EXPECT_EQ(g.errors()[0].where, "/parameters/0/step") << all_messages(g.errors());
  }
}

// A pass type that takes only odd sizes; the graph parameter bound to it must say so too.
PassTypeRegistry odd_registry() {
  PassTypeRegistry r;
  register_generic_pass_types(r);
  PassTypeDecl box;
  box.name = "odd_box";
  box.slots = {{"input", Access::read, SlotKind::texture, {}, Usage::sampled, true},
               {"output", Access::write, SlotKind::texture, {}, Usage::image_store, true}};
  box.params = {odd_size()};
  r.add(box);
  return r;
}

GraphErrors compile_with(const std::string& param) {
  auto g = parse_graph_json(R"({"name": "t", "parameters": [)" + param + R"(],
    "resources": {"a": {"kind": "persistent", "format": "R16F", "size": "screen"},
                  "b": {"kind": "texture", "format": "R16F", "size": "screen"}},
    "passes": [{"type": "odd_box", "name": "box", "slots": {"input": "a", "output": "b"}, "params": {"box_size": "$box_size"}}],
    "outputs": ["b"]})", "t.json");
  if (!g) return g.errors();
  ParameterSet params(g->parameters);
  auto plan = compile(*g, odd_registry(), params, small_settings(), {});
  return plan ? GraphErrors{} : plan.errors();
}

TEST(ParamStep, AGraphParameterBoundToAnOddOnlyPassParameterMustBeOddOnly) {
  GraphErrors any = compile_with(R"({"name": "box_size", "type": "int", "default": 5, "min": 1, "max": 15})");
  ASSERT_TRUE(has_code(any, GraphErrorCode::param_range_mismatch)) << all_messages(any);
  EXPECT_NE(all_messages(any).find("steps of 2 from 1"), std::string::npos) << all_messages(any);
  GraphErrors even = compile_with(R"({"name": "box_size", "type": "int", "default": 6, "min": 2, "max": 14, "step": 2})");
  EXPECT_TRUE(has_code(even, GraphErrorCode::param_range_mismatch)) << all_messages(even);
  // Odd, or a coarser grid of odd values (1, 5, 9, ...), fits.
  GraphErrors odd = compile_with(R"({"name": "box_size", "type": "int", "default": 5, "min": 1, "max": 15, "step": 2})");
  EXPECT_TRUE(odd.empty()) << all_messages(odd);
  EXPECT_TRUE(compile_with(R"({"name": "box_size", "type": "int", "default": 5, "min": 1, "max": 13, "step": 4})").empty());
}

TEST(ParamApplies, ConditionsMayReadAnyParameterAndAreChecked) {
  auto ok = parse_graph_json(R"({"name": "x", "parameters": [
    {"name": "kernel", "type": "enum", "options": ["box", "vogel"], "default": "box"},
    {"name": "samples", "type": "int", "default": 16, "min": 1, "max": 64, "applies": "$kernel == \"vogel\""}],
    "passes": []})", "a.json");
  ASSERT_TRUE(ok) << all_messages(ok.errors());
  EXPECT_EQ(ok->parameters[1].applies, "$kernel == \"vogel\"");
  struct Bad {
    const char* applies;
    const char* says;
  };
  for (const Bad& b : {Bad{R"($kernel == \"hex\")", "hex"}, Bad{R"($nope)", "nope"}, Bad{R"($kernel ==)", "kernel"},
                       Bad{R"($samples)", "samples"}}) {
    auto g = parse_graph_json(std::string(R"({"name": "x", "parameters": [
      {"name": "kernel", "type": "enum", "options": ["box", "vogel"], "default": "box"},
      {"name": "samples", "type": "int", "default": 16, "applies": ")") + b.applies + R"("}], "passes": []})", "a.json");
    ASSERT_FALSE(g) << b.applies;
    EXPECT_EQ(g.errors()[0].where, "/parameters/1/applies") << all_messages(g.errors());
    EXPECT_NE(all_messages(g.errors()).find(b.says), std::string::npos) << all_messages(g.errors());
  }
}

TEST(ParamCappedBy, ReadAndChecked) {
  const std::string head = R"({"name": "x", "parameters": [
    {"name": "kernel", "type": "enum", "options": ["box", "vogel"], "default": "box"},
    {"name": "max_size", "type": "float", "default": 0.04, "min": 0.001, "max": 0.05},
    {"name": "scale", "type": "float", "default": 1.2, "min": 1, "max": 2, "capped_by": )";
  auto ok = parse_graph_json(head + R"({"param": "max_size", "when": "$kernel == \"vogel\"", "why": "w"}}], "passes": []})", "a.json");
  ASSERT_TRUE(ok) << all_messages(ok.errors());
  ASSERT_TRUE(ok->parameters[2].capped_by.has_value());
  EXPECT_EQ(ok->parameters[2].capped_by->param, "max_size");
  EXPECT_EQ(ok->parameters[2].capped_by->when, "$kernel == \"vogel\"");
  struct Bad {
    const char* cap;
    const char* where;
    const char* says;
  };
  for (const Bad& b : {Bad{R"({"param": "nope", "why": "w"})", "/parameters/2/capped_by/param", "nope"},
                       Bad{R"({"param": "scale", "why": "w"})", "/parameters/2/capped_by/param", "itself"},
                       Bad{R"({"param": "max_size", "when": "$kernel == \"hex\"", "why": "w"})", "/parameters/2/capped_by/when", "hex"},
                       Bad{R"({"param": "max_size"})", "/parameters/2/capped_by", "why"},
                       Bad{R"({"param": "max_size", "why": "w", "by": 1})", "/parameters/2/capped_by", "by"},
                       Bad{R"("max_size")", "/parameters/2/capped_by", "object"}}) {
    auto g = parse_graph_json(head + b.cap + R"(}], "passes": []})", "a.json");
    ASSERT_FALSE(g) << b.cap;
    EXPECT_EQ(g.errors()[0].where.rfind(b.where, 0), 0u) << b.cap << ": " << all_messages(g.errors());
    EXPECT_NE(all_messages(g.errors()).find(b.says), std::string::npos) << all_messages(g.errors());
  }
}

}  // namespace
}  // namespace penumbra::graph
