// The binding rule of graph_desc.h and the format features built on it: defaults of unbound
// pass parameters, range agreement between a $-bound graph parameter and the pass type, choices
// ({"if"} / {"switch"}) resolved per parameter set, templates, sizes divided by a parameter,
// and the rule that everything that shapes the plan reads structural parameters only.
#include <gtest/gtest.h>

#include "graph/graph_json.h"
#include "test_registry.h"

namespace penumbra::graph {
namespace {

using namespace testing;

// A graph with `params` (JSON array body) and `passes` after a camera depth pass writing "depth".
std::string graph(const std::string& params, const std::string& passes, const std::string& extra = "") {
  return R"({"name": "t", "parameters": [)" + params + R"(],)" + extra + R"(
  "resources": {
    "scene": {"kind": "imported"}, "camera": {"kind": "imported"},
    "depth": {"kind": "texture", "format": "DEPTH32F", "size": "screen"},
    "blocker": {"kind": "texture", "format": "R16F", "size": "screen"},
    "mask": {"kind": "texture", "format": "R16F", "size": "screen"},
    "small": {"kind": "texture", "format": "R16F", "size": "screen/$div"}
  },
  "passes": [
    {"type": "depth_prepass", "name": "camera_depth", "slots": {"scene": "scene", "camera": "camera", "depth": "depth"}},
    )" + passes + R"(
  ],
  "outputs": ["mask"]})";
}

const char* kDiv = R"({"name": "div", "type": "int", "default": 2, "min": 1, "max": 8, "structural": true})";

struct Compiled {
  GraphErrors errors;
  std::optional<CompiledPlan> plan;
};

Compiled compile_text(const std::string& text, const std::vector<std::string>& sets = {}) {
  Compiled c;
  auto g = parse_graph_json(text, "t.json");
  if (!g) {
    c.errors = g.errors();
    return c;
  }
  ParameterSet params(g->parameters);
  for (const auto& s : sets) EXPECT_TRUE(params.set_from_string(s)) << s;
  auto plan = compile(*g, generic_registry(), params, small_settings());
  if (plan) c.plan = std::move(*plan);
  else c.errors = plan.errors();
  return c;
}

const PlannedParam& param_of(const CompiledPlan& plan, const std::string& pass, const std::string& name) {
  for (const auto& p : plan.passes)
    if (p.name == pass)
      for (const auto& pp : p.params)
        if (pp.name == name) return pp;
  static PlannedParam none;
  ADD_FAILURE() << "no parameter " << name << " on pass " << pass;
  return none;
}

const GraphError& error_with(const GraphErrors& errors, GraphErrorCode code) {
  for (const auto& e : errors)
    if (e.code == code) return e;
  static GraphError none;
  ADD_FAILURE() << "no error " << graph_error_code_name(code) << " in:\n" << all_messages(errors);
  return none;
}

const std::string kFilter = R"({"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask"}})";

TEST(GraphBinding, UnboundPassParametersKeepThePassTypesDefault) {
  auto c = compile_text(graph(kDiv, kFilter));
  ASSERT_TRUE(c.plan) << all_messages(c.errors);
  EXPECT_EQ(param_of(*c.plan, "filter", "kernel").reference, "");
  EXPECT_EQ(std::get<std::string>(param_of(*c.plan, "filter", "kernel").value), "vogel");
  EXPECT_EQ(std::get<int>(param_of(*c.plan, "filter", "samples").value), 16);
}

TEST(GraphBinding, BoundParameterWhoseRangeLeavesThePassRangeIsRejected) {
  // samples: the pass type accepts [1, 64]; the graph parameter allows up to 128, so a user
  // could set a value the pass cannot take.
  auto bind = [](const std::string& param, const std::string& pass_param) {
    return std::string(R"({"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask"}, "params": {")") + pass_param + R"(": "$)" + param + "\"}}";
  };
  const std::string wide = std::string(R"({"name": "taps", "type": "int", "default": 16, "min": 1, "max": 128},)") + kDiv;
  auto c = compile_text(graph(wide, bind("taps", "samples")));
  const GraphError& e = error_with(c.errors, GraphErrorCode::param_range_mismatch);
  for (const char* word : {"t.json", "/passes/1/params/samples", "filter", "$taps", "/parameters/0", "[1, 128]", "[1, 64]"})
    EXPECT_NE(e.to_string().find(word), std::string::npos) << "missing " << word << " in " << e.to_string();
  // Unbounded, other enum options, another unit: each a mismatch too.
  auto unbounded = compile_text(graph(std::string(R"({"name": "taps", "type": "int", "default": 16},)") + kDiv, bind("taps", "samples")));
  EXPECT_NE(error_with(unbounded.errors, GraphErrorCode::param_range_mismatch).message.find("no range"), std::string::npos);
  auto options = compile_text(graph(std::string(R"({"name": "shape", "type": "enum", "default": "box", "options": ["box", "hex"]},)") + kDiv, bind("shape", "kernel")));
  EXPECT_NE(error_with(options.errors, GraphErrorCode::param_range_mismatch).message.find("\"hex\""), std::string::npos);
  auto unit = compile_text(graph(std::string(R"({"name": "size", "type": "float", "default": 1, "min": 0, "max": 2, "unit": "texels"},)") + kDiv, bind("size", "light_size")));
  EXPECT_NE(error_with(unit.errors, GraphErrorCode::param_range_mismatch).message.find("unit"), std::string::npos);
  // Inside the pass range: fine.
  auto narrow = compile_text(graph(std::string(R"({"name": "taps", "type": "int", "default": 16, "min": 4, "max": 32},)") + kDiv, bind("taps", "samples")));
  EXPECT_TRUE(narrow.plan) << all_messages(narrow.errors);
}

TEST(GraphBinding, ChoicesPickSlotsAndParametersPerParameterSet) {
  const std::string params = std::string(R"({"name": "blocked", "type": "bool", "default": false, "structural": true},
    {"name": "kernel", "type": "enum", "default": "box", "options": ["box", "vogel"], "structural": true},)") + kDiv;
  const std::string passes = R"({"type": "blocker_search", "name": "search", "enabled": "$blocked",
     "slots": {"shadow_map": "depth", "depth": "depth", "blocker": "blocker"}},
    {"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask",
               "blocker": {"if": "$blocked", "then": "blocker"}},
     "params": {"kernel": "$kernel", "samples": {"switch": "$kernel", "cases": {"box": 9, "vogel": 32}},
                "light_size": {"if": "$blocked", "then": 2.5, "else": null}}})";
  auto off = compile_text(graph(params, passes));
  ASSERT_TRUE(off.plan) << all_messages(off.errors);
  EXPECT_EQ(off.plan->passes.size(), 2u);
  EXPECT_EQ(off.plan->passes[1].bindings.size(), 3u);  // no blocker slot
  EXPECT_EQ(std::get<int>(param_of(*off.plan, "filter", "samples").value), 9);
  EXPECT_DOUBLE_EQ(std::get<double>(param_of(*off.plan, "filter", "light_size").value), 0.5);  // null: type default

  auto on = compile_text(graph(params, passes), {"blocked=true", "kernel=vogel"});
  ASSERT_TRUE(on.plan) << all_messages(on.errors);
  ASSERT_EQ(on.plan->passes.size(), 3u);
  bool reads_blocker = false;
  for (const auto& b : on.plan->passes[2].bindings) reads_blocker = reads_blocker || b.resource == "blocker";
  EXPECT_TRUE(reads_blocker);
  EXPECT_EQ(std::get<int>(param_of(*on.plan, "filter", "samples").value), 32);
  EXPECT_DOUBLE_EQ(std::get<double>(param_of(*on.plan, "filter", "light_size").value), 2.5);
}

TEST(GraphBinding, NestedChoiceWithoutElseLeavesTheSlotUnboundNotTheOuterElse) {
  const std::string params = std::string(R"({"name": "a", "type": "bool", "default": true, "structural": true},
    {"name": "b", "type": "bool", "default": false, "structural": true},)") + kDiv;
  const std::string passes = R"({"type": "blocker_search", "name": "search",
     "slots": {"shadow_map": "depth", "depth": "depth", "blocker": "blocker"}},
    {"type": "penumbra_filter", "name": "filter", "slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask",
     "blocker": {"if": "$a", "then": {"if": "$b", "then": "blocker"}, "else": "blocker"}}})";
  auto c = compile_text(graph(params, passes));  // a && !b: unbound
  ASSERT_TRUE(c.plan) << all_messages(c.errors);
  EXPECT_EQ(c.plan->passes.back().bindings.size(), 3u);
  EXPECT_EQ(c.plan->culled, std::vector<std::string>{"search"});
}

TEST(GraphBinding, ChoicesAndConditionsReadStructuralParametersOnly) {
  const std::string params = std::string(R"({"name": "live", "type": "bool", "default": true},)") + kDiv;
  auto c = compile_text(graph(params, R"({"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask"},
     "params": {"samples": {"if": "$live", "then": 4}}})"));
  const GraphError& e = error_with(c.errors, GraphErrorCode::param_not_structural);
  EXPECT_NE(e.to_string().find("/passes/1/params/samples/then"), std::string::npos) << e.to_string();
  EXPECT_NE(e.message.find("structural"), std::string::npos);
  auto enabled = compile_text(graph(params, kFilter + R"(,
    {"type": "blur", "name": "b", "enabled": "$live", "slots": {"input": "mask", "output": "mask"}})"));
  EXPECT_EQ(error_with(enabled.errors, GraphErrorCode::param_not_structural).where, "/passes/2/enabled");
}

TEST(GraphBinding, ComparingAnEnumWithAnUnknownOptionIsAnError) {
  const std::string params = std::string(R"({"name": "v", "type": "enum", "default": "a", "options": ["a", "b"], "structural": true},)") + kDiv;
  auto c = compile_text(graph(params, kFilter + R"(,
    {"type": "blur", "name": "b", "enabled": "$v == \"c\"", "slots": {"input": "mask", "output": "mask"}})"));
  EXPECT_NE(error_with(c.errors, GraphErrorCode::bad_condition).message.find("not an option"), std::string::npos);
  auto sw = compile_text(graph(params, R"({"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask"},
     "params": {"samples": {"switch": "$v", "cases": {"a": 4, "typo": 8}}}})"));
  EXPECT_NE(error_with(sw.errors, GraphErrorCode::bad_condition).message.find("not an option"), std::string::npos);
}

TEST(GraphBinding, TemplatesGiveSlotsAndParametersOncePassesOverrideThem) {
  const std::string templates = R"("templates": {
    "filtered": {"type": "penumbra_filter", "slots": {"shadow_map": "depth", "depth": "depth"},
                 "params": {"samples": 8, "kernel": "box"}}},)";
  auto c = compile_text(graph(kDiv, R"({"extends": "filtered", "name": "f1", "slots": {"mask": "mask"}, "side_effect": true},
    {"extends": ["filtered"], "name": "f2", "slots": {"mask": "mask"}, "params": {"samples": 12}})", templates));
  ASSERT_TRUE(c.plan) << all_messages(c.errors);
  EXPECT_EQ(c.plan->passes[1].type, "penumbra_filter");
  EXPECT_EQ(c.plan->passes[1].bindings[0].slot, "shadow_map");  // the template's order first
  EXPECT_EQ(std::get<int>(param_of(*c.plan, "f1", "samples").value), 8);
  EXPECT_EQ(std::get<int>(param_of(*c.plan, "f2", "samples").value), 12);
  EXPECT_EQ(std::get<std::string>(param_of(*c.plan, "f2", "kernel").value), "box");
  auto unknown = compile_text(graph(kDiv, R"({"extends": "nope", "name": "f", "type": "blur"})", templates));
  ASSERT_FALSE(unknown.errors.empty());
  EXPECT_NE(unknown.errors[0].message.find("no template named 'nope'; templates: filtered"), std::string::npos)
      << all_messages(unknown.errors);
}

TEST(GraphBinding, SizeDividedByAParameterFollowsItsValue) {
  const std::string passes = R"({"type": "blocker_search", "name": "search",
     "slots": {"shadow_map": "depth", "depth": "depth", "blocker": "small"}},
    {"type": "blur", "name": "reader", "slots": {"input": "small", "output": "mask"}})";
  auto full = compile_text(graph(kDiv, passes), {"div=1"});
  ASSERT_TRUE(full.plan) << all_messages(full.errors);
  EXPECT_EQ(full.plan->physical.at(full.plan->physical_for("small")).width, 256);
  for (int div : {2, 4}) {
    // blur's input and output must have the same size: small (screen/div) vs mask (screen).
    auto c = compile_text(graph(kDiv, passes), {"div=" + std::to_string(div)});
    const GraphError& e = error_with(c.errors, GraphErrorCode::size_mismatch);
    EXPECT_NE(e.message.find(std::to_string(256 / div) + "x" + std::to_string(128 / div)), std::string::npos) << e.message;
  }
  auto live = compile_text(graph(R"({"name": "div", "type": "int", "default": 2, "min": 1, "max": 8})", kFilter));
  EXPECT_EQ(error_with(live.errors, GraphErrorCode::param_not_structural).where, "/resources/small/size");
  auto wide = compile_text(graph(R"({"name": "div", "type": "int", "default": 2, "min": 1, "max": 100, "structural": true})", kFilter));
  EXPECT_NE(error_with(wide.errors, GraphErrorCode::param_range_mismatch).message.find("[1, 64]"), std::string::npos);
  auto missing = compile_text(graph(R"({"name": "x", "type": "int", "default": 2, "min": 1, "max": 4, "structural": true})", kFilter));
  error_with(missing.errors, GraphErrorCode::unknown_param_reference);
}

// A texture's format chosen by a structural parameter: "$param" (an enum whose options are format
// names) or a choice of names. The chosen format is the one validated and planned.
std::string format_graph(const std::string& params, const std::string& format) {
  return R"({"name": "t", "parameters": [)" + params + R"(],
  "resources": {
    "scene": {"kind": "imported"}, "camera": {"kind": "imported"},
    "depth": {"kind": "texture", "format": "DEPTH32F", "size": "screen"},
    "blocker": {"kind": "texture", "format": "R16F", "size": "screen"},
    "mask": {"kind": "texture", "format": )" + format + R"(, "size": "screen"}
  },
  "passes": [
    {"type": "depth_prepass", "name": "camera_depth", "slots": {"scene": "scene", "camera": "camera", "depth": "depth"}},
    {"type": "blocker_search", "name": "search", "slots": {"shadow_map": "depth", "depth": "depth", "blocker": "blocker"}},
    {"type": "blur", "name": "b", "slots": {"input": "blocker", "output": "mask"}}
  ],
  "outputs": ["mask"]})";
}

TEST(GraphBinding, AFormatChosenByAParameterIsTheOneValidatedAndPlanned) {
  const std::string fmt =
      R"({"name": "fmt", "type": "enum", "default": "R16F", "options": ["R16F", "RGBA16F", "R32F"], "structural": true})";
  auto format_of = [](const Compiled& c) { return c.plan->physical.at(c.plan->physical_for("mask")).format; };
  auto half = compile_text(format_graph(fmt, R"("$fmt")"));
  ASSERT_TRUE(half.plan) << all_messages(half.errors);
  EXPECT_EQ(format_of(half), Format::R16F);
  auto wide = compile_text(format_graph(fmt, R"("$fmt")"), {"fmt=RGBA16F"});
  ASSERT_TRUE(wide.plan) << all_messages(wide.errors);
  EXPECT_EQ(format_of(wide), Format::RGBA16F);
  // blur's output takes R8, R16F or RGBA16F: the chosen R32F is refused where it is bound.
  auto refused = compile_text(format_graph(fmt, R"("$fmt")"), {"fmt=R32F"});
  EXPECT_NE(error_with(refused.errors, GraphErrorCode::format_not_accepted).message.find("format R32F"), std::string::npos);

  const std::string precision =
      R"({"name": "precision", "type": "enum", "default": "half", "options": ["half", "low"], "structural": true})";
  const std::string choice = R"({"switch": "$precision", "cases": {"half": "R16F", "low": "R8"}})";
  auto low = compile_text(format_graph(precision, choice), {"precision=low"});
  ASSERT_TRUE(low.plan) << all_messages(low.errors);
  EXPECT_EQ(format_of(low), Format::R8);
}

TEST(GraphBinding, AFormatParameterMustBeAStructuralEnumOfFormatNames) {
  auto live = compile_text(format_graph(
      R"({"name": "fmt", "type": "enum", "default": "R16F", "options": ["R16F", "R8"]})", R"("$fmt")"));
  EXPECT_EQ(error_with(live.errors, GraphErrorCode::param_not_structural).where, "/resources/mask/format");
  auto typo = compile_text(format_graph(
      R"({"name": "fmt", "type": "enum", "default": "R16F", "options": ["R16F", "R61F"], "structural": true})", R"("$fmt")"));
  const GraphError& unknown = error_with(typo.errors, GraphErrorCode::wrong_json_type);
  EXPECT_EQ(unknown.where, "/resources/mask/format");
  EXPECT_NE(unknown.message.find("unknown format \"R61F\""), std::string::npos) << unknown.message;
  auto number = compile_text(format_graph(
      R"({"name": "n", "type": "int", "default": 1, "min": 1, "max": 2, "structural": true})", R"("$n")"));
  EXPECT_NE(error_with(number.errors, GraphErrorCode::param_wrong_type).message.find("it is not an enum"), std::string::npos);
  auto missing = compile_text(format_graph(kDiv, R"("$nope")"));
  error_with(missing.errors, GraphErrorCode::unknown_param_reference);
}

}  // namespace
}  // namespace penumbra::graph
