// Golden plan dumps of every shipped technique graph, composed into the frame, at its default
// parameters (1920x1080, 2048^2 shadow map), and of the documented examples: a change of the
// graph format or of a technique's JSON must not change what runs unless the dump's diff says
// so. After an intended change, regenerate with
//   PENUMBRA_UPDATE_GOLDEN=1 ./technique_plan_tests
// and review the diff like code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "graph/compiler.h"
#include "graph/exposures.h"
#include "graph/graph_json.h"
#include "technique/frame_graph.h"
#include "technique/preset.h"
#include "technique/technique_session.h"
#include "techniques/_template/template_technique.h"
#include "techniques/builtin_techniques.h"

namespace penumbra {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Techniques {
  technique::TechniqueRegistry registry;
  exec::PassLibrary library;
  Techniques() {
    register_builtin_techniques(registry);
    template_technique::register_technique(registry);
    library = make_pass_library(registry);
  }
};

const Techniques& techniques() {
  static const Techniques t;
  return t;
}

// The plan must equal the golden file, or (PENUMBRA_UPDATE_GOLDEN=1) becomes it.
void expect_golden(const std::string& text, const std::string& golden) {
  const char* update = std::getenv("PENUMBRA_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    std::ofstream(golden, std::ios::binary) << text;
    GTEST_SKIP() << "updated " << golden;
  }
  const std::string expected = read_file(golden);
  ASSERT_FALSE(expected.empty()) << golden << " missing; run with PENUMBRA_UPDATE_GOLDEN=1";
  EXPECT_EQ(text, expected) << "plan changed against " << golden
                            << "; if intended, regenerate with PENUMBRA_UPDATE_GOLDEN=1 and review the diff";
}

class TechniquePlan : public ::testing::TestWithParam<const char*> {};

TEST_P(TechniquePlan, DefaultPlanMatchesGoldenDump) {
  const std::string name = GetParam();
  const technique::Technique* technique = techniques().registry.find(name);
  ASSERT_NE(technique, nullptr) << name;
  auto declared = technique::load_technique_graph(*technique, techniques().library.declarations());
  ASSERT_TRUE(declared) << declared.error().to_string() << "\n" << declared.error().details;
  auto frame = technique::compose_frame_graph(*declared);
  ASSERT_TRUE(frame) << frame.error().to_string();
  graph::ParameterSet params(frame->parameters);
  auto plan = graph::compile(*frame, techniques().library.declarations(), params, {1920, 1080, 2048});
  ASSERT_TRUE(plan) << technique::errors_to_error(plan.errors()).details;
  expect_golden(graph::to_text(*plan), std::string(PENUMBRA_TEST_DATA_DIR) + "/golden/techniques/" + name + ".txt");
}

// Every value of every structural parameter, in every combination (int ranges of up to 16
// values, by the parameter's step), compiles: a variant no default exercises cannot rot unseen.
TEST_P(TechniquePlan, EveryStructuralCombinationCompiles) {
  const technique::Technique* technique = techniques().registry.find(GetParam());
  ASSERT_NE(technique, nullptr);
  auto frame = technique::compose_frame_graph(*technique::load_technique_graph(*technique, techniques().library.declarations()));
  ASSERT_TRUE(frame);
  std::vector<std::pair<std::string, std::vector<graph::ParamValue>>> axes;
  for (const graph::ParamDesc& d : frame->parameters) {
    if (!d.structural) continue;
    std::vector<graph::ParamValue> values;
    if (d.type == graph::ParamType::boolean) values = {false, true};
    if (d.type == graph::ParamType::enumeration)
      for (const std::string& o : d.options) values.push_back(o);
    if (d.type == graph::ParamType::integer && d.max - d.min < 16)
      for (int v = static_cast<int>(d.min); v <= static_cast<int>(d.max); v += std::max(1, static_cast<int>(d.step)))
        values.push_back(v);
    if (!values.empty()) axes.emplace_back(d.name, values);
  }
  std::vector<size_t> index(axes.size(), 0);
  int compiled = 0;
  for (bool more = true; more; ++compiled) {
    graph::ParameterSet params(frame->parameters);
    std::string combination;
    for (size_t a = 0; a < axes.size(); ++a) {
      ASSERT_TRUE(params.set(axes[a].first, axes[a].second[index[a]]));
      combination += axes[a].first + "=" + graph::param_value_to_string(axes[a].second[index[a]]) + " ";
    }
    auto plan = graph::compile(*frame, techniques().library.declarations(), params, {640, 360, 1024});
    ASSERT_TRUE(plan) << combination << "\n" << technique::errors_to_error(plan.errors()).details;
    more = false;
    for (size_t a = 0; a < axes.size() && !more; ++a) {
      if (++index[a] < axes[a].second.size()) more = true;
      else index[a] = 0;
    }
  }
  RecordProperty("combinations", compiled);
}

// The documented examples (docs/graph-examples) compile against the real pass types, as
// `penumbra graph FILE` does: composed into the frame when they read its resources.
class DocumentedExample : public ::testing::TestWithParam<const char*> {};

TEST_P(DocumentedExample, PlanMatchesGoldenDump) {
  const std::string name = GetParam();
  const std::string path = std::string(PENUMBRA_SOURCE_DIR) + "/docs/graph-examples/" + name + ".json";
  auto declared = graph::load_graph_json(path);
  ASSERT_TRUE(declared) << technique::errors_to_error(declared.errors()).details;
  graph::GraphDesc desc = *declared;
  graph::GraphErrors unresolved = graph::resolve_exposures(desc, techniques().library.declarations());
  ASSERT_TRUE(unresolved.empty()) << technique::errors_to_error(unresolved).details;
  if (technique::reads_frame_resources(desc)) {
    auto frame = technique::compose_frame_graph(desc);
    ASSERT_TRUE(frame) << frame.error().to_string();
    desc = *frame;
  }
  graph::ParameterSet params(desc.parameters);
  auto plan = graph::compile(desc, techniques().library.declarations(), params, {1920, 1080, 2048});
  ASSERT_TRUE(plan) << technique::errors_to_error(plan.errors()).details;
  expect_golden(graph::to_text(*plan), std::string(PENUMBRA_TEST_DATA_DIR) + "/golden/" + name + ".txt");
}

INSTANTIATE_TEST_SUITE_P(Docs, DocumentedExample,
                         ::testing::Values("pcss_blur", "penumbra_variants", "progressive_reference"));

// No parameter is described twice: a technique parameter that binds a pass parameter with "$"
// must not repeat its description, or its default and range (then it should expose it); and
// no description a technique states is stated by another technique or by a pass type.
TEST(OneDescription, NoTechniqueRepeatsADescriptionADefaultOrARange) {
  const graph::PassTypeRegistry& types = techniques().library.declarations();
  std::map<std::string, std::string> pass_descriptions;  // description -> "type.param"
  for (const std::string& type : types.names())
    for (const graph::ParamDesc& d : types.find(type)->params) pass_descriptions.emplace(d.description, type + "." + d.name);
  std::map<std::string, std::string> stated;  // description -> "technique.param"
  int checked = 0;
  for (const technique::Technique& t : techniques().registry.all()) {
    // As written in the file: an exposing parameter's description is there only if it states one.
    auto raw = graph::load_graph_json(std::string(PENUMBRA_SOURCE_DIR) + "/" + t.graph_file);
    ASSERT_TRUE(raw) << t.graph_file;
    for (const graph::ParamDesc& d : raw->parameters) {
      if (d.description.empty()) continue;
      const std::string who = t.name + "." + d.name;
      auto [it, fresh] = stated.emplace(d.description, who);
      EXPECT_TRUE(fresh) << who << " states the description of " << it->second << ": \"" << d.description << "\"";
      if (auto p = pass_descriptions.find(d.description); p != pass_descriptions.end())
        ADD_FAILURE() << who << " states the description of pass parameter " << p->second << "; expose it instead";
      ++checked;
    }
    auto resolved = technique::load_technique_graph(t, types);
    ASSERT_TRUE(resolved) << resolved.error().details;
    for (const graph::PassDecl& p : resolved->passes) {
      const graph::PassTypeDecl* type = types.find(p.type);
      ASSERT_NE(type, nullptr) << p.type;
      for (const graph::ParamBinding& b : p.params) {
        const graph::ParamDesc* pass_param = type->find_param(b.name);
        auto technique_param = std::find_if(resolved->parameters.begin(), resolved->parameters.end(),
                                            [&](const graph::ParamDesc& d) { return d.name == b.reference; });
        if (b.reference.empty() || !pass_param || technique_param == resolved->parameters.end()) continue;
        const bool exposes = std::any_of(resolved->exposures.begin(), resolved->exposures.end(),
                                         [&](const graph::ParamExposure& e) { return e.parameter == b.reference; });
        if (exposes) continue;  // inherited, never restated (resolve_exposures refuses that)
        const bool same_default_and_range = technique_param->default_value == pass_param->default_value &&
                                            technique_param->min == pass_param->min &&
                                            technique_param->max == pass_param->max;
        EXPECT_FALSE(same_default_and_range) << t.name << "." << b.reference << " repeats the default and range of "
                                             << p.type << "." << b.name << ": expose it";
      }
    }
  }
  EXPECT_GE(checked, 10);
}

// A technique parameter may not take the name of a frame pass's parameter: the frame's
// lighting pass would look as if the technique set it.
TEST(FrameParameters, ATechniqueParameterNamedLikeTheLightingPassesIsRefused) {
  const technique::Technique* hard = techniques().registry.find("hard");
  ASSERT_NE(hard, nullptr);
  auto declared = technique::load_technique_graph(*hard, techniques().library.declarations());
  ASSERT_TRUE(declared);
  graph::GraphDesc desc = *declared;
  desc.source_file = "hard.json";
  graph::ParamDesc ambient = desc.parameters.front();
  ambient.name = "ambient";
  desc.parameters.push_back(ambient);
  auto frame = technique::compose_frame_graph(desc);
  ASSERT_TRUE(frame) << frame.error().to_string();
  graph::ParameterSet params(frame->parameters);
  auto plan = graph::compile(*frame, techniques().library.declarations(), params, {256, 128, 512});
  ASSERT_FALSE(plan);
  bool named = false;
  for (const graph::GraphError& e : plan.errors())
    if (e.code == graph::GraphErrorCode::param_shadows_frame)
      named = e.to_string().find("lighting") != std::string::npos && e.to_string().find("ambient") != std::string::npos &&
              e.to_string().find("hard.json") != std::string::npos;
  EXPECT_TRUE(named) << technique::errors_to_error(plan.errors()).details;
}

// Every paper technique ships its paper's constants as the `paper` preset, and each shipped
// preset fits its technique's parameters and compiles.
TEST(ShippedPresets, PaperPresetsApplyToTheirTechniquesAndCompile) {
  const technique::TechniqueRegistry& registry = techniques().registry;
  for (const char* name : {"pcss", "pmchss", "mpg", "sspcss", "esm"}) {
    const technique::Technique* technique = registry.find(name);
    ASSERT_NE(technique, nullptr) << name;
    std::vector<std::string> shipped = technique::shipped_presets(*technique);
    EXPECT_NE(std::find(shipped.begin(), shipped.end(), "paper"), shipped.end()) << name;
    auto desc = technique::load_technique_graph(*technique, techniques().library.declarations());
    ASSERT_TRUE(desc) << desc.error().to_string();
    for (const std::string& preset_name : shipped) {
      auto preset = technique::load_preset(*technique, preset_name);
      ASSERT_TRUE(preset) << preset.error().to_string();
      graph::ParameterSet defaults(desc->parameters);
      auto applied = technique::preset_applied(*preset, name, defaults);
      ASSERT_TRUE(applied) << name << "@" << preset_name << ": " << applied.error().to_string();
      // PCSS is physically driven in the paper already (Fernando 2005): its defaults are its paper.
      if (std::string(name) != "pcss") {
        EXPECT_NE(applied->to_json(), defaults.to_json()) << name << "@" << preset_name << " is the defaults";
      }
      auto frame = technique::compose_frame_graph(*desc);
      ASSERT_TRUE(frame) << frame.error().to_string();
      auto plan = graph::compile(*frame, techniques().library.declarations(), *applied, {1920, 1080, 2048});
      EXPECT_TRUE(plan) << name << "@" << preset_name;
    }
  }
}

TEST(ShippedPresets, UnknownPresetNamesTheShippedOnes) {
  const technique::Technique* pmchss = techniques().registry.find("pmchss");
  ASSERT_NE(pmchss, nullptr);
  auto missing = technique::load_preset(*pmchss, "papr");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("shipped: paper"), std::string::npos) << missing.error().message;
  const technique::Technique* hard = techniques().registry.find("hard");
  ASSERT_NE(hard, nullptr);
  auto none = technique::load_preset(*hard, "paper");
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().message.find("ships none"), std::string::npos) << none.error().message;
}

INSTANTIATE_TEST_SUITE_P(Shipped, TechniquePlan,
                         ::testing::Values("hard", "pcf", "pcss", "pmchss", "reference", "sspcss", "template", "esm", "mpg"));

}  // namespace
}  // namespace penumbra
