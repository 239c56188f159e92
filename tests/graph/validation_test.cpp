// One test per validation error kind: each asserts the code, and that the message names the
// pass, slot, resource and location (JSON pointer) it is about. And: all errors at once.
#include <gtest/gtest.h>

#include "graph/graph_json.h"
#include "test_registry.h"

namespace penumbra::graph {
namespace {

using namespace testing;

// Parameters the tests read; a graph declares only those it uses (one nothing reads is an error).
const char* kRadius = R"({"name": "radius", "type": "int", "default": 2, "min": 1, "max": 16})";
const char* kFlag = R"({"name": "flag", "type": "bool", "default": true, "structural": true})";
const char* kN = R"({"name": "n", "type": "int", "default": 100, "min": 1, "max": 1000, "structural": true})";

// A valid graph; each test swaps one piece of `passes` for a broken one.
std::string graph_with(const std::string& passes, const std::string& params = "") {
  return R"({"name": "t",
  "parameters": [)" + params + R"(],
  "resources": {
    "scene": {"kind": "imported"}, "camera": {"kind": "imported"}, "light": {"kind": "imported"},
    "depth": {"kind": "texture", "format": "DEPTH32F", "size": "screen"},
    "half": {"kind": "texture", "format": "R16F", "size": "screen/2"},
    "mask": {"kind": "texture", "format": "R16F", "size": "screen"},
    "rgba8": {"kind": "texture", "format": "RGBA8", "size": "screen"}
  },
  "passes": [
    {"type": "depth_prepass", "name": "camera_depth",
     "slots": {"scene": "scene", "camera": "camera", "depth": "depth"}},
    )" + passes + R"(
  ],
  "outputs": ["mask"]})";
}

const std::string kFilter = R"({"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask"}})";

GraphErrors errors_of(const std::string& text) {
  auto g = parse_graph_json(text, "t.json");
  if (!g) return g.errors();
  auto plan = compile_graph(*g);
  return plan ? GraphErrors{} : plan.errors();
}

const GraphError& only(const GraphErrors& errors, GraphErrorCode code) {
  for (const auto& e : errors)
    if (e.code == code) return e;
  static GraphError none;
  ADD_FAILURE() << "no error " << graph_error_code_name(code) << " in:\n" << all_messages(errors);
  return none;
}

void expect_mentions(const GraphError& e, std::initializer_list<const char*> words) {
  std::string text = e.to_string();
  EXPECT_NE(text.find("t.json"), std::string::npos) << text;
  for (const char* w : words) EXPECT_NE(text.find(w), std::string::npos) << "missing '" << w << "' in " << text;
}

TEST(GraphValidation, ValidBaseGraphCompiles) {
  EXPECT_TRUE(errors_of(graph_with(kFilter)).empty()) << all_messages(errors_of(graph_with(kFilter)));
}

TEST(GraphValidation, UnknownPassType) {
  auto e = only(errors_of(graph_with(kFilter + R"(, {"type": "bluur", "name": "b1", "slots": {}})")),
                GraphErrorCode::unknown_pass_type);
  expect_mentions(e, {"/passes/2", "b1", "bluur", "blur"});  // lists the known types
}

TEST(GraphValidation, UnknownSlot) {
  auto e = only(errors_of(graph_with(R"({"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask", "maks": "mask"}})")),
                GraphErrorCode::unknown_slot);
  expect_mentions(e, {"/passes/1/slots/maks", "filter", "maks", "mask"});
}

TEST(GraphValidation, MissingRequiredSlot) {
  auto e = only(errors_of(graph_with(R"({"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "mask": "mask"}})")),
                GraphErrorCode::missing_required_slot);
  expect_mentions(e, {"/passes/1", "filter", "'depth'", "required"});
}

TEST(GraphValidation, ReadWithNoProducer) {
  auto e = only(errors_of(graph_with(R"({"type": "blur", "name": "early_blur",
     "slots": {"input": "half", "output": "mask"}})")),
                GraphErrorCode::read_without_producer);
  expect_mentions(e, {"/passes/1/slots/input", "early_blur", "input", "half@0", "no producer"});
}

TEST(GraphValidation, Cycle) {
  auto e = only(errors_of(graph_with(kFilter + R"(,
    {"type": "blur", "name": "a", "slots": {"input": "mask@3", "output": "mask@2"}},
    {"type": "blur", "name": "b", "slots": {"input": "mask@2", "output": "mask@3"}})")),
                GraphErrorCode::cycle);
  expect_mentions(e, {"/passes/2", "cycle", "'a'", "'b'"});
}

TEST(GraphValidation, TwoWritersOfOneVersion) {
  auto e = only(errors_of(graph_with(kFilter + R"(,
    {"type": "blur", "name": "second", "slots": {"input": "mask@1", "output": "mask@1"}})")),
                GraphErrorCode::two_writers);
  expect_mentions(e, {"/passes/2/slots/output", "second", "output", "mask@1", "filter"});
}

TEST(GraphValidation, FormatNotAcceptedBySlot) {
  auto e = only(errors_of(graph_with(R"({"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "rgba8"}})")),
                GraphErrorCode::format_not_accepted);
  expect_mentions(e, {"/passes/1/slots/mask", "filter", "mask", "rgba8", "RGBA8", "R16F"});
}

TEST(GraphValidation, SizeMismatchInSameSizeGroup) {
  auto e = only(errors_of(graph_with(kFilter + R"(,
    {"type": "blur", "name": "downsample", "slots": {"input": "mask", "output": "half"}})")),
                GraphErrorCode::size_mismatch);
  expect_mentions(e, {"/passes/2/slots/output", "downsample", "output", "half", "128x64", "256x128"});
}

TEST(GraphValidation, ParameterWrongType) {
  auto e = only(errors_of(graph_with(R"({"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask"}, "params": {"samples": "many"}})")),
                GraphErrorCode::param_wrong_type);
  expect_mentions(e, {"/passes/1/params/samples", "filter", "samples", "int"});
}

TEST(GraphValidation, ParameterOutOfRange) {
  auto e = only(errors_of(graph_with(R"({"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask"}, "params": {"samples": 1000}})")),
                GraphErrorCode::param_out_of_range);
  expect_mentions(e, {"/passes/1/params/samples", "filter", "samples", "1000", "[1, 64]"});
}

TEST(GraphValidation, UnknownParameterReference) {
  auto e = only(errors_of(graph_with(R"({"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "mask"}, "params": {"samples": "$taps"}})")),
                GraphErrorCode::unknown_param_reference);
  expect_mentions(e, {"/passes/1/params/samples", "filter", "$taps"});
}

TEST(GraphValidation, RepeatOutOfRange) {
  auto e = only(errors_of(graph_with(kFilter + R"(,
    {"type": "blur_in_place", "name": "smooth", "repeat": "$n", "slots": {"image": "mask"}})", kN)),
                GraphErrorCode::repeat_out_of_range);
  expect_mentions(e, {"/passes/2/repeat", "smooth", "$n", "[1, 1000]", "[1, 64]"});
  auto constant = only(errors_of(graph_with(kFilter + R"(,
    {"type": "blur_in_place", "name": "smooth", "repeat": 0, "slots": {"image": "mask"}})")),
                       GraphErrorCode::repeat_out_of_range);
  expect_mentions(constant, {"/passes/2/repeat", "smooth"});
}

TEST(GraphValidation, VersionsPastTheLimitAreErrorsNamingPassAndResource) {
  auto pinned = only(errors_of(graph_with(kFilter + R"(,
    {"type": "blur", "name": "late", "slots": {"input": "mask", "output": "mask@1024"}},
    {"type": "blur", "name": "later", "slots": {"input": "mask", "output": "mask"}})")),
                     GraphErrorCode::version_out_of_range);
  expect_mentions(pinned, {"/passes/3/slots/output", "later", "mask", "1025", "1024"});
  // An in-place chain of 17 x 64 writes runs past the limit: an error, not dropped writes.
  std::string chain = kFilter;
  for (int i = 0; i < 17; ++i)
    chain += R"(, {"type": "blur_in_place", "name": "s)" + std::to_string(i) + R"(", "repeat": 64, "slots": {"image": "mask"}})";
  auto long_chain = only(errors_of(graph_with(chain)), GraphErrorCode::version_out_of_range);
  expect_mentions(long_chain, {"s15[", "mask", "1025"});
}

TEST(GraphValidation, BadCondition) {
  auto e = only(errors_of(graph_with(kFilter + R"(,
    {"type": "blur_in_place", "name": "smooth", "enabled": "$flag &&", "slots": {"image": "mask"}})", kFlag)),
                GraphErrorCode::bad_condition);
  expect_mentions(e, {"/passes/2/enabled", "smooth"});
  auto typed = only(errors_of(graph_with(kFilter + R"(,
    {"type": "blur_in_place", "name": "smooth", "enabled": "$radius", "slots": {"image": "mask"}})", kRadius)),
                    GraphErrorCode::bad_condition);
  expect_mentions(typed, {"radius", "not bool"});
}

TEST(GraphValidation, AllErrorsReportedAtOnce) {
  auto errors = errors_of(graph_with(R"({"type": "bluur", "name": "x", "slots": {}},
    {"type": "penumbra_filter", "name": "filter",
     "slots": {"shadow_map": "depth", "depth": "depth", "mask": "rgba8", "oops": "mask"},
     "params": {"samples": 1000, "kernel": 3, "light_size": "$nope"}},
    {"type": "blur", "name": "b", "repeat": 99, "slots": {"input": "half", "output": "mask"}})"));
  for (auto code : {GraphErrorCode::unknown_pass_type, GraphErrorCode::unknown_slot,
                    GraphErrorCode::format_not_accepted, GraphErrorCode::param_out_of_range,
                    GraphErrorCode::param_wrong_type, GraphErrorCode::unknown_param_reference,
                    GraphErrorCode::repeat_out_of_range, GraphErrorCode::size_mismatch})
    EXPECT_TRUE(has_code(errors, code)) << graph_error_code_name(code) << "\n" << all_messages(errors);
  EXPECT_GE(errors.size(), 8u);
}

TEST(GraphValidation, BuilderGraphErrorsNameThePass) {
  GraphBuilder b("builder");
  auto mask = b.texture("mask", Format::R16F, SizeExpr::screen());
  b.pass("blur", "lonely").read("input", mask).write("output", mask);
  b.output(mask);
  auto plan = compile_graph(b.build());
  ASSERT_FALSE(plan);
  const auto& e = plan.errors().at(0);
  EXPECT_EQ(e.code, GraphErrorCode::read_without_producer);
  EXPECT_NE(e.to_string().find("pass 'lonely'"), std::string::npos) << e.to_string();
}

}  // namespace
}  // namespace penumbra::graph
