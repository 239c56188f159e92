// Templates and choices as the reader expands them (docs/graph-format.md, "Templates and
// choices: the grammar"): what a pass gets from `extends`, in which order, from where, and
// the bindings and `when` conditions an {"if"} / {"switch"} value becomes.
#include <gtest/gtest.h>

#include "graph/graph_json.h"
#include "test_registry.h"

namespace penumbra::graph {
namespace {

using namespace testing;

std::string slots_of(const PassDecl& p) {
  std::string out;
  for (const SlotBinding& b : p.slots) out += b.slot + "=" + b.resource + "@" + b.location + " ";
  return out;
}

int errors_at(const GraphErrors& errors, const std::string& where) {
  int n = 0;
  for (const GraphError& e : errors) n += e.where == where;
  return n;
}

TEST(GraphTemplates, ExtendsAppliesTemplatesInOrderThenThePassLaterEntriesReplacingInPlace) {
  auto g = parse_graph_json(R"({"name": "t", "templates": {
      "a": {"type": "ta", "enabled": "$x", "slots": {"s1": "r1", "s2": "r2"}, "params": {"p1": 1}},
      "b": {"type": "tb", "enabled": "$y", "slots": {"s2": "q2", "s3": "q3"}, "params": {"p1": 2, "p2": 3}}},
    "passes": [
      {"extends": ["a", "b"], "name": "both", "enabled": "$z", "slots": {"s1": "own1", "s4": "own4"}, "params": {"p2": 4}},
      {"extends": ["b", "a"], "name": "reversed", "type": "own"},
      {"extends": "a", "name": "one"}]})", "t.json");
  ASSERT_TRUE(g) << all_messages(g.errors());
  const PassDecl& both = g->passes[0];
  EXPECT_EQ(both.type, "tb");  // the last template's
  EXPECT_EQ(both.enabled, "(($x) && ($y)) && ($z)");  // every one given must hold
  // s1 keeps the first template's position with the pass's value; s2 the later template's value.
  EXPECT_EQ(slots_of(both), "s1=own1@/passes/0/slots/s1 s2=q2@/templates/b/slots/s2 s3=q3@/templates/b/slots/s3 "
                            "s4=own4@/passes/0/slots/s4 ");
  ASSERT_EQ(both.params.size(), 2u);
  EXPECT_EQ(both.params[0].location, "/templates/b/params/p1");
  EXPECT_EQ(std::get<int>(both.params[0].constant), 2);
  EXPECT_EQ(both.params[1].location, "/passes/0/params/p2");
  EXPECT_EQ(std::get<int>(both.params[1].constant), 4);

  const PassDecl& reversed = g->passes[1];
  EXPECT_EQ(reversed.type, "own");  // the pass's own over any template's
  EXPECT_EQ(reversed.enabled, "($y) && ($x)");
  EXPECT_EQ(slots_of(reversed), "s2=r2@/templates/a/slots/s2 s3=q3@/templates/b/slots/s3 s1=r1@/templates/a/slots/s1 ");

  EXPECT_EQ(g->passes[2].type, "ta");
  EXPECT_EQ(g->passes[2].enabled, "$x");  // one condition stays as written
}

TEST(GraphTemplates, ATemplatesEnabledIsReadLikeAPassesBoolIncluded) {
  auto g = parse_graph_json(R"({"name": "t", "templates": {"off": {"enabled": false}, "on": {"enabled": "$x"}},
    "passes": [{"extends": ["on", "off"], "name": "p", "type": "blur"}, {"extends": "off", "name": "q", "type": "blur"}]})");
  ASSERT_TRUE(g) << all_messages(g.errors());
  EXPECT_EQ(g->passes[0].enabled, "($x) && (false)");
  EXPECT_EQ(g->passes[1].enabled, "false");
  // Compiled, a template's `false` removes the pass.
  auto disabled = parse_graph_json(R"({"name": "t", "templates": {"off": {"enabled": false}},
    "resources": {"scene": {"kind": "imported"}, "camera": {"kind": "imported"},
                  "d": {"kind": "texture", "format": "DEPTH32F", "size": "screen"}},
    "passes": [{"type": "depth_prepass", "name": "z", "slots": {"scene": "scene", "camera": "camera", "depth": "d"}},
               {"extends": "off", "type": "depth_prepass", "name": "gone", "side_effect": true,
                "slots": {"scene": "scene", "camera": "camera", "depth": "d"}}],
    "outputs": ["d"]})");
  ASSERT_TRUE(disabled) << all_messages(disabled.errors());
  auto plan = compile_graph(*disabled);
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  ASSERT_EQ(plan->passes.size(), 1u);
  EXPECT_EQ(plan->passes[0].name, "z");
}

TEST(GraphTemplates, ATemplateIsCheckedOnceWhereItIsDeclared) {
  // Wrong types in a template are errors even if no pass extends it, reported once however
  // many passes extend it.
  auto g = parse_graph_json(R"({"name": "t", "templates": {
      "bad": {"type": 3, "enabled": 4, "slots": 5, "params": []},
      "unused": {"type": [], "slotz": {}}},
    "passes": [{"extends": "bad", "name": "p", "type": "blur"}, {"extends": "bad", "name": "q", "type": "blur"}]})",
                            "t.json");
  ASSERT_FALSE(g);
  for (const char* where : {"/templates/bad/type", "/templates/bad/enabled", "/templates/bad/slots",
                            "/templates/bad/params", "/templates/unused/type", "/templates/unused/slotz"})
    EXPECT_EQ(errors_at(g.errors(), where), 1) << where << "\n" << all_messages(g.errors());
  EXPECT_EQ(g.errors().size(), 6u) << all_messages(g.errors());
}

TEST(GraphTemplates, AnEntryFromATemplatePointsIntoItAndNamesEachPassExtendingIt) {
  auto g = parse_graph_json(R"({"name": "t", "templates": {"t": {"params": {"radius": [1]}}},
    "passes": [{"extends": "t", "name": "p", "type": "blur"}, {"extends": "t", "name": "q", "type": "blur"}]})");
  ASSERT_FALSE(g);
  ASSERT_EQ(g.errors().size(), 2u) << all_messages(g.errors());
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(g.errors()[i].where, "/templates/t/params/radius");
    EXPECT_EQ(g.errors()[i].code, GraphErrorCode::param_wrong_type);
    EXPECT_NE(g.errors()[i].message.find(i == 0 ? "pass 'p'" : "pass 'q'"), std::string::npos) << g.errors()[i].message;
  }
  auto unknown = parse_graph_json(R"({"name": "t", "passes": [{"extends": ["t", 3], "name": "p", "type": "blur"}]})");
  ASSERT_FALSE(unknown);
  ASSERT_EQ(unknown.errors().size(), 2u) << all_messages(unknown.errors());
  EXPECT_NE(unknown.errors()[0].message.find("no template named 't'; templates: (none)"), std::string::npos);
  EXPECT_NE(unknown.errors()[1].message.find("a template name or an array of them"), std::string::npos);
}

TEST(GraphChoices, IfAndSwitchExpandIntoBindingsUnderConditionsInTheOrderWritten) {
  auto g = parse_graph_json(R"({"name": "t", "parameters": [
      {"name": "f", "type": "bool", "default": true, "structural": true},
      {"name": "n", "type": "int", "default": 2, "structural": true},
      {"name": "v", "type": "enum", "options": ["a", "b", "c"], "default": "a", "structural": true}],
    "passes": [{"type": "blur", "name": "p",
      "slots": {"s": {"if": "$f", "then": "r1", "else": {"switch": "$v", "cases": {"a": "ra", "b": null}, "default": "rd"}}},
      "params": {"k": {"switch": "$n", "cases": {"2": 5, "-1": "$other"}}, "g": {"switch": "$f", "cases": {"true": 1}}}}]})");
  ASSERT_TRUE(g) << all_messages(g.errors());
  const PassDecl& p = g->passes[0];
  ASSERT_EQ(p.slots.size(), 4u);
  const std::string not_f = "!($f)";
  const struct { std::string resource, location, when; } slots[] = {
      {"r1", "/passes/0/slots/s/then", "$f"},
      {"ra", "/passes/0/slots/s/else/cases/a", "(" + not_f + ") && ($v == \"a\")"},
      {"", "/passes/0/slots/s/else/cases/b", "(" + not_f + ") && ($v == \"b\")"},  // null: unbound
      {"rd", "/passes/0/slots/s/else/default", "(" + not_f + ") && ((!($v == \"a\")) && (!($v == \"b\")))"},
  };
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(p.slots[i].resource, slots[i].resource) << i;
    EXPECT_EQ(p.slots[i].location, slots[i].location) << i;
    EXPECT_EQ(p.slots[i].when, slots[i].when) << i;
  }
  ASSERT_EQ(p.params.size(), 3u);
  EXPECT_EQ(p.params[0].when, "$n == 2");
  EXPECT_EQ(std::get<int>(p.params[0].constant), 5);
  EXPECT_EQ(p.params[1].when, "$n == -1");
  EXPECT_EQ(p.params[1].reference, "other");
  EXPECT_EQ(p.params[2].when, "$f == true");
  EXPECT_EQ(p.params[2].location, "/passes/0/params/g/cases/true");
}

TEST(GraphChoices, ACaseMustBeAValueOfTheSwitchedParametersType) {
  auto g = parse_graph_json(R"({"name": "t", "parameters": [
      {"name": "f", "type": "bool", "default": true, "structural": true},
      {"name": "n", "type": "int", "default": 2, "structural": true},
      {"name": "v", "type": "enum", "options": ["a"], "default": "a", "structural": true}],
    "passes": [{"type": "blur", "name": "p", "params": {
      "a": {"switch": "$n", "cases": {"two": 1}}, "b": {"switch": "$f", "cases": {"yes": 1}},
      "c": {"switch": "$v", "cases": {"a\"": 1}}, "d": {"switch": "$nope", "cases": {"x": 1}},
      "e": {"switch": "v", "cases": {}}, "f": {"if": true, "then": 1}, "g": {"then": 1}}}]})");
  ASSERT_FALSE(g);
  const struct { const char* where; GraphErrorCode code; } expected[] = {
      {"/passes/0/params/a/cases/two", GraphErrorCode::bad_condition},
      {"/passes/0/params/b/cases/yes", GraphErrorCode::bad_condition},
      {"/passes/0/params/c/cases/a\"", GraphErrorCode::bad_condition},
      {"/passes/0/params/d/cases/x", GraphErrorCode::unknown_param_reference},
      {"/passes/0/params/e", GraphErrorCode::wrong_json_type},
      {"/passes/0/params/f", GraphErrorCode::wrong_json_type},
      {"/passes/0/params/g", GraphErrorCode::wrong_json_type},
  };
  ASSERT_EQ(g.errors().size(), std::size(expected)) << all_messages(g.errors());
  for (size_t i = 0; i < std::size(expected); ++i) {
    EXPECT_EQ(g.errors()[i].where, expected[i].where) << i;
    EXPECT_EQ(g.errors()[i].code, expected[i].code) << i;
  }
}

}  // namespace
}  // namespace penumbra::graph
