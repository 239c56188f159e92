// The JSON parser on malformed and hostile input: always errors, never a crash or exception.
#include <gtest/gtest.h>

#include <random>

#include "graph/condition.h"
#include "graph/graph_json.h"
#include "test_registry.h"

namespace penumbra::graph {
namespace {

using namespace testing;

TEST(GraphJson, MalformedJsonReportsLineAndColumn) {
  auto g = parse_graph_json("{\n  \"name\": \"x\",\n  \"passes\": [,]\n}", "bad.json");
  ASSERT_FALSE(g);
  const auto& e = g.errors().at(0);
  EXPECT_EQ(e.code, GraphErrorCode::malformed_json);
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.column, 14);
  EXPECT_EQ(e.to_string().rfind("bad.json:3:14: ", 0), 0u) << e.to_string();
}

TEST(GraphJson, DeepNestingIsRefusedBeforeParsing) {
  std::string deep(100000, '[');
  auto g = parse_graph_json(deep, "deep.json");
  ASSERT_FALSE(g);
  EXPECT_EQ(g.errors()[0].code, GraphErrorCode::malformed_json);
  EXPECT_NE(g.errors()[0].message.find("nesting"), std::string::npos);
  // Brackets inside strings do not count.
  std::string in_string = "{\"name\": \"" + std::string(1000, '[') + "\", \"passes\": []}";
  EXPECT_TRUE(parse_graph_json(in_string));
}

TEST(GraphJson, HostileContentNeverCrashes) {
  const std::string cases[] = {
      "", " ", "null", "[]", "42", "\"str\"", "{", "}", "{\"passes\": 1}",
      "{\"passes\": [1, \"x\", null, []]}",
      "{\"passes\": [{\"type\": 1, \"name\": [], \"slots\": 3, \"params\": [], \"repeat\": {}}]}",
      "{\"passes\": [{\"type\": \"blur\", \"name\": \"b\", \"repeat\": 1e308}]}",
      "{\"passes\": [{\"type\": \"blur\", \"name\": \"b\", \"repeat\": -99999999999999999999999}]}",
      "{\"passes\": [{\"type\": \"blur\", \"name\": \"b\", \"params\": {\"radius\": 1e999}}]}",
      "{\"passes\": [{\"type\": \"blur\", \"name\": \"b\", \"slots\": {\"input\": \"m@99999999\"}}]}",
      "{\"resources\": {\"t\": {\"kind\": \"texture\", \"format\": \"RGBA8\", \"size\": \"99999999x1\"}}, \"passes\": []}",
      "{\"resources\": {\"t\": {\"kind\": \"buffer\", \"bytes\": 18446744073709551615}}, \"passes\": []}",
      "{\"resources\": {\"t\": {\"kind\": \"texture\", \"format\": \"RGBA8\", \"size\": \"screen/0\"}}, \"passes\": []}",
      "{\"resources\": [], \"parameters\": {}, \"outputs\": \"x\", \"passes\": []}",
      "{\"parameters\": [{\"name\": \"x\", \"type\": \"int\", \"default\": \"y\", \"min\": \"a\"}], \"passes\": []}",
      "{\"name\": \"\xff\xfe\", \"passes\": []}",
      "\xef\xbb\xbf{\"passes\": []}",
      "{\"passes\": []}\x00garbage",
      "{\"passes\": [{\"type\": \"blur\", \"name\": \"b\", \"enabled\": \"((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((($x\"}]}",
  };
  for (const auto& text : cases) {
    auto g = parse_graph_json(text, "hostile.json");
    if (g) {
      auto plan = compile_graph(*g);  // whatever parsed must compile or report, not crash
      (void)plan;
      continue;
    }
    ASSERT_FALSE(g.errors().empty());
    for (const auto& e : g.errors()) EXPECT_FALSE(e.message.empty());
  }
}

TEST(GraphJson, WrongTypesEverywhereAreAllReported) {
  auto g = parse_graph_json(R"({"name": 5, "resources": {"a": {"kind": "texture", "format": 3, "size": true}},
    "passes": [{"type": "blur", "name": "b", "slots": {"input": 4}, "enabled": 3, "side_effect": "yes"}],
    "outputs": [1]})", "types.json");
  ASSERT_FALSE(g);
  EXPECT_GE(g.errors().size(), 7u) << all_messages(g.errors());
  for (const auto& e : g.errors()) EXPECT_EQ(e.where.substr(0, 1), "/") << e.to_string();
}

TEST(GraphJson, RandomBytesFuzz) {
  std::mt19937 rng(7);
  const std::string seed = R"({"name":"t","resources":{"m":{"kind":"texture","format":"R8","size":"screen"}},"passes":[{"type":"blur","name":"b","slots":{"input":"m","output":"m"},"repeat":2}],"outputs":["m"]})";
  for (int i = 0; i < 2000; ++i) {
    std::string text = seed;
    int edits = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < edits; ++k) text[rng() % text.size()] = static_cast<char>(rng() % 256);
    auto g = parse_graph_json(text, "fuzz.json");
    if (g) (void)compile_graph(*g);
  }
  SUCCEED();
}

TEST(GraphJson, ExampleRoundTripThroughBuilderModel) {
  auto g = parse_graph_json(R"({"name": "one", "parameters": [{"name": "r", "type": "int", "default": 2, "min": 1, "max": 8, "structural": true}],
    "resources": {"scene": {"kind": "imported"}, "camera": {"kind": "imported"},
                  "d": {"kind": "texture", "format": "DEPTH32F", "size": "screen/$r"}},
    "passes": [{"type": "depth_prepass", "name": "z", "slots": {"scene": "scene", "camera": "camera", "depth": "d"}}],
    "outputs": ["d"]})", "one.json");
  ASSERT_TRUE(g) << all_messages(g.errors());
  EXPECT_EQ(g->resources[2].size.to_string(), "screen/$r");
  EXPECT_EQ(g->passes[0].location, "/passes/0");
  auto plan = compile_graph(*g);
  ASSERT_TRUE(plan);
  EXPECT_EQ(plan->physical.at(0).width, 128);
}

TEST(GraphJson, DuplicateKeysAreErrorsNamingBothPlaces) {
  // A second "passes" would silently wipe the first.
  auto g = parse_graph_json("{\"name\": \"x\", \"passes\": [],\n  \"passes\": []}", "dup.json");
  ASSERT_FALSE(g);
  const GraphError& e = g.errors().at(0);
  EXPECT_EQ(e.code, GraphErrorCode::malformed_json);
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.column, 3);
  EXPECT_NE(e.message.find("duplicate key \"passes\" (first at 1:15)"), std::string::npos) << e.message;
  // Equal keys in different objects are fine.
  EXPECT_TRUE(parse_graph_json(R"({"name": "x", "resources": {"a": {"kind": "imported"}, "b": {"kind": "imported"}}, "passes": []})"));
}

TEST(GraphJson, DuplicateParameterNamesAreErrorsNamingBoth) {
  auto g = parse_graph_json(R"({"name": "x", "parameters": [
    {"name": "n", "type": "int", "default": 1, "min": 0, "max": 2},
    {"name": "n", "type": "bool", "default": true}], "passes": []})", "p.json");
  ASSERT_FALSE(g);
  const GraphError& e = g.errors().at(0);
  EXPECT_EQ(e.code, GraphErrorCode::duplicate_name);
  EXPECT_EQ(e.where, "/parameters/1/name");
  EXPECT_NE(e.message.find("/parameters/0"), std::string::npos) << e.message;
}

TEST(GraphJson, OverflowingNumbersAreReportedWhereTheyAreInOneShortLine) {
  for (const std::string& number : {std::string("1e999"), std::string(100000, '7')}) {
    auto g = parse_graph_json("{\"name\": \"x\",\n \"passes\": [{\"repeat\": " + number + "}]}", "n.json");
    ASSERT_FALSE(g);
    const GraphError& e = g.errors().at(0);
    EXPECT_EQ(e.line, 2);
    EXPECT_EQ(e.column, 24);
    EXPECT_LT(e.to_string().size(), 200u) << e.to_string().substr(0, 300);
  }
}

TEST(GraphJson, LongOperatorChainsNeverRecurse) {
  // A few hundred terms (the longest a condition may be): parsed and evaluated iteratively.
  std::string chain = "$flag";
  while (chain.size() + 12 < kMaxConditionLength) chain += " || !$flag";
  auto g = parse_graph_json(R"({"name": "c", "parameters": [{"name": "flag", "type": "bool", "default": false, "structural": true}],
    "resources": {"scene": {"kind": "imported"}, "camera": {"kind": "imported"},
                  "d": {"kind": "texture", "format": "DEPTH32F", "size": "screen"}},
    "passes": [{"type": "depth_prepass", "name": "z", "enabled": ")" + chain + R"(",
                "slots": {"scene": "scene", "camera": "camera", "depth": "d"}}],
    "outputs": ["d"]})", "c.json");
  ASSERT_TRUE(g) << all_messages(g.errors());
  auto plan = compile_graph(*g);
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  EXPECT_EQ(plan->passes.size(), 1u);
  // Hundreds of kB of terms: refused with a short message, no stack overflow.
  std::string huge = "$flag";
  for (int i = 0; i < 40000; ++i) huge += " || $flag && $flag";
  g->passes[0].enabled = huge;
  plan = compile_graph(*g);
  ASSERT_FALSE(plan);
  EXPECT_EQ(plan.errors()[0].code, GraphErrorCode::bad_condition);
  EXPECT_NE(plan.errors()[0].message.find("characters long"), std::string::npos);
  EXPECT_LT(plan.errors()[0].message.size(), 200u);
}

}  // namespace
}  // namespace penumbra::graph
