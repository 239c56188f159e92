// The rules that make parameter bindings explicit and checked (docs/graph-format.md
// "Parameters"): one test per rule, each on the smallest graph that breaks it, asserting the
// error code and that the message names both places involved.
#include <gtest/gtest.h>

#include "graph/exposures.h"
#include "graph/graph_json.h"
#include "test_registry.h"

namespace penumbra::graph {
namespace {

using namespace testing;

// `params` (a JSON array body) and `passes` after a camera depth pass writing "depth"; the
// filter pass writes the output "mask".
std::string graph(const std::string& params, const std::string& passes) {
  return R"({"name": "t", "parameters": [)" + params + R"(],
  "resources": {
    "scene": {"kind": "imported"}, "camera": {"kind": "imported"},
    "depth": {"kind": "texture", "format": "DEPTH32F", "size": "screen"},
    "mask": {"kind": "texture", "format": "R16F", "size": "screen"},
    "blurred": {"kind": "texture", "format": "R16F", "size": "screen"}
  },
  "passes": [
    {"type": "depth_prepass", "name": "camera_depth", "slots": {"scene": "scene", "camera": "camera", "depth": "depth"}},
    )" + passes + R"(
  ],
  "outputs": ["mask", "blurred"]})";
}

const char* kFilterSlots = R"("slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask"})";

std::string filter(const std::string& params = "") {
  return std::string(R"({"type": "penumbra_filter", "name": "filter", )") + kFilterSlots +
         (params.empty() ? "" : ", \"params\": {" + params + "}") + "}";
}

struct Outcome {
  GraphErrors errors;           // from parsing, resolving or compiling, whichever failed first
  std::optional<GraphDesc> graph;
  std::optional<CompiledPlan> plan;
};

Outcome build(const std::string& text) {
  Outcome o;
  auto g = parse_graph_json(text, "t.json");
  if (!g) {
    o.errors = g.errors();
    return o;
  }
  if (GraphErrors e = resolve_exposures(*g, generic_registry()); !e.empty()) {
    o.errors = e;
    return o;
  }
  o.graph = *g;
  ParameterSet params(g->parameters);
  auto plan = compile(*g, generic_registry(), params, small_settings());
  if (plan) o.plan = std::move(*plan);
  else o.errors = plan.errors();
  return o;
}

const GraphError& error_with(const Outcome& o, GraphErrorCode code) {
  for (const auto& e : o.errors)
    if (e.code == code) return e;
  static GraphError none;
  ADD_FAILURE() << "no error " << graph_error_code_name(code) << " in:\n" << all_messages(o.errors);
  return none;
}

void expect_mentions(const GraphError& e, std::initializer_list<const char*> words) {
  const std::string text = e.to_string();
  for (const char* w : words) EXPECT_NE(text.find(w), std::string::npos) << "missing '" << w << "' in: " << text;
}

const PlannedParam* planned(const CompiledPlan& plan, const std::string& pass, const std::string& name) {
  for (const auto& p : plan.passes)
    if (p.name == pass)
      for (const auto& pp : p.params)
        if (pp.name == name) return &pp;
  return nullptr;
}

TEST(ExposedParameter, InheritsThePassTypesDescriptionAndBindsThePassParameter) {
  Outcome o = build(graph(R"({"name": "taps", "exposes": "filter.samples", "default": 24})", filter()));
  ASSERT_TRUE(o.plan) << all_messages(o.errors);
  const ParamDesc& taps = o.graph->parameters.at(0);
  EXPECT_EQ(taps.type, ParamType::integer);
  EXPECT_EQ(taps.min, 1);
  EXPECT_EQ(taps.max, 64);
  EXPECT_EQ(taps.description, generic_registry().find("penumbra_filter")->find_param("samples")->description);
  EXPECT_FALSE(taps.description.empty());
  const PlannedParam* samples = planned(*o.plan, "filter", "samples");
  ASSERT_NE(samples, nullptr);
  EXPECT_EQ(samples->reference, "taps");
  EXPECT_EQ(std::get<int>(samples->value), 24);
}

TEST(ExposedParameter, MayNarrowTheRangeAndRestateNothingElse) {
  Outcome narrow = build(graph(R"({"name": "taps", "exposes": "filter.samples", "min": 4, "max": 32})", filter()));
  ASSERT_TRUE(narrow.plan) << all_messages(narrow.errors);
  EXPECT_EQ(narrow.graph->parameters.at(0).max, 32);
  // Saying again what the pass type says is describing it twice.
  Outcome same = build(graph(R"({"name": "taps", "exposes": "filter.samples", "default": 16})", filter()));
  expect_mentions(error_with(same, GraphErrorCode::param_described_twice), {"t.json", "/parameters/0/exposes", "default"});
  const std::string text = generic_registry().find("penumbra_filter")->find_param("samples")->description;
  Outcome described = build(graph(R"({"name": "taps", "exposes": "filter.samples", "description": ")" + text + "\"}", filter()));
  expect_mentions(error_with(described, GraphErrorCode::param_described_twice), {"description"});
}

TEST(BindingRules, AParameterThatReachesNoPassInAnyVariantIsAnError) {
  // The shape of pm-CHSS's checker_depth_epsilon: declared, described, read by nothing.
  Outcome o = build(graph(R"({"name": "taps", "exposes": "filter.samples"},
                             {"name": "epsilon", "type": "float", "default": 0.001, "min": 1e-6, "max": 10})",
                          filter()));
  expect_mentions(error_with(o, GraphErrorCode::param_unreached), {"t.json", "/parameters/1", "'epsilon'"});
  // Read by a condition of a branch the defaults do not take, it reaches the graph.
  Outcome used = build(graph(R"({"name": "taps", "exposes": "filter.samples"},
                                {"name": "blur", "type": "bool", "default": false, "structural": true})",
                             filter() + R"(, {"type": "blur", "name": "soften", "enabled": "$blur",
                                             "slots": {"input": "mask", "output": "blurred"}})"));
  EXPECT_TRUE(used.plan) << all_messages(used.errors);
}

TEST(BindingRules, ABindingToAParameterThePassTypeDoesNotDeclareIsAnError) {
  Outcome bound = build(graph(R"({"name": "taps", "type": "int", "default": 8, "min": 1, "max": 64})",
                              filter(R"("sample_count": "$taps")")));
  expect_mentions(error_with(bound, GraphErrorCode::param_unknown), {"/passes/1/params/sample_count", "samples"});
  Outcome exposed = build(graph(R"({"name": "taps", "exposes": "filter.sample_count", "default": 8})", filter()));
  expect_mentions(error_with(exposed, GraphErrorCode::param_unknown), {"/parameters/0/exposes", "penumbra_filter", "samples"});
}

TEST(BindingRules, APassParameterWithNeitherBindingNorDefaultIsAnError) {
  const std::string blur = R"({"type": "directional_blur", "name": "soften", "slots": {"input": "mask", "output": "blurred"})";
  Outcome unbound = build(graph("", filter() + ", " + blur + "}"));
  expect_mentions(error_with(unbound, GraphErrorCode::param_unbound), {"/passes/2", "soften", "'axis'", "no default"});
  Outcome bound = build(graph("", filter() + ", " + blur + R"(, "params": {"axis": "y"}})"));
  EXPECT_TRUE(bound.plan) << all_messages(bound.errors);
  // Exposing it needs a default of the technique's own.
  Outcome exposed = build(graph(R"({"name": "direction", "exposes": "soften.axis"})", filter() + ", " + blur + "}"));
  expect_mentions(error_with(exposed, GraphErrorCode::param_unbound), {"/parameters/0/exposes", "no default"});
}

TEST(BindingRules, APassParameterLeftUnboundBesideAGraphParameterOfItsNameIsAnError) {
  // What binding by name did silently; now it says how to bind.
  Outcome o = build(graph(R"({"name": "samples", "type": "int", "default": 8, "min": 1, "max": 64},
                             {"name": "taps", "exposes": "filter.light_size", "default": 1.0})",
                          filter()));
  expect_mentions(error_with(o, GraphErrorCode::param_unbound),
                  {"/passes/1", "'samples'", "/parameters/0", "$samples", "filter.samples"});
}

TEST(BindingRules, ATypeMismatchIsAnError) {
  Outcome bound = build(graph(R"({"name": "taps", "type": "bool", "default": true})", filter(R"("samples": "$taps")")));
  expect_mentions(error_with(bound, GraphErrorCode::param_wrong_type), {"/passes/1/params/samples", "expects int", "bool"});
  Outcome exposed = build(graph(R"({"name": "taps", "exposes": "filter.samples", "type": "float", "default": 2})", filter()));
  expect_mentions(error_with(exposed, GraphErrorCode::param_wrong_type), {"/parameters/0/exposes", "float", "int"});
}

TEST(BindingRules, ATechniqueRangeWiderThanThePassAcceptsIsAnError) {
  Outcome bound = build(graph(R"({"name": "taps", "type": "int", "default": 8, "min": 1, "max": 128})",
                              filter(R"("samples": "$taps")")));
  expect_mentions(error_with(bound, GraphErrorCode::param_range_mismatch), {"/passes/1/params/samples", "[1, 128]", "[1, 64]"});
  Outcome exposed = build(graph(R"({"name": "taps", "exposes": "filter.samples", "min": 0})", filter()));
  expect_mentions(error_with(exposed, GraphErrorCode::param_range_mismatch), {"/parameters/0/exposes", "[0, 64]", "[1, 64]"});
}

TEST(BindingRules, BindingAPassParameterTwiceNamesBothPlaces) {
  Outcome o = build(graph(R"({"name": "taps", "exposes": "filter.samples"},
                             {"name": "more", "type": "int", "default": 8, "min": 1, "max": 64})",
                          filter(R"("samples": "$more")")));
  expect_mentions(error_with(o, GraphErrorCode::param_bound_twice), {"/passes/1/params/samples", "/parameters/0/exposes", "'taps'"});
  Outcome twice = build(graph(R"({"name": "taps", "exposes": "filter.samples"},
                                 {"name": "more", "exposes": "filter.samples", "default": 8})",
                              filter()));
  expect_mentions(error_with(twice, GraphErrorCode::param_bound_twice), {"/parameters/1/exposes", "/parameters/0/exposes", "'taps'"});
}

TEST(BindingRules, ExposingAPassTheGraphDoesNotDeclareIsAnError) {
  Outcome o = build(graph(R"({"name": "taps", "exposes": "filtre.samples"})", filter()));
  expect_mentions(error_with(o, GraphErrorCode::unknown_pass), {"/parameters/0/exposes", "'filtre'", "filter"});
  Outcome malformed = build(graph(R"({"name": "taps", "exposes": "samples"})", filter()));
  expect_mentions(error_with(malformed, GraphErrorCode::wrong_json_type), {"/parameters/0/exposes", "pass.parameter"});
}

TEST(BindingRules, CompilingUnresolvedExposuresIsRefusedNotSilentlyUnbound) {
  auto g = parse_graph_json(graph(R"({"name": "taps", "exposes": "filter.samples", "default": 24})", filter()), "t.json");
  ASSERT_TRUE(g);
  ParameterSet params(g->parameters);
  auto plan = compile(*g, generic_registry(), params, small_settings());
  ASSERT_FALSE(plan);
  EXPECT_TRUE(has_code(plan.errors(), GraphErrorCode::exposure_unresolved)) << all_messages(plan.errors());
}

}  // namespace
}  // namespace penumbra::graph
