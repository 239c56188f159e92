// Golden plan dumps of every shipped technique graph, composed into the frame, at its default
// parameters (1920x1080, 2048^2 shadow map): a change of the graph format or of a technique's
// JSON must not change what runs unless the dump's diff says so. After an intended change,
// regenerate with
//   PENUMBRA_UPDATE_GOLDEN=1 ./technique_plan_tests
// and review the diff like code.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "graph/compiler.h"
#include "plugin/frame_graph.h"
#include "plugin/technique_session.h"
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
  plugin::TechniqueRegistry registry;
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

class TechniquePlan : public ::testing::TestWithParam<const char*> {};

TEST_P(TechniquePlan, DefaultPlanMatchesGoldenDump) {
  const std::string name = GetParam();
  const plugin::Technique* technique = techniques().registry.find(name);
  ASSERT_NE(technique, nullptr) << name;
  auto declared = plugin::load_technique_graph(*technique);
  ASSERT_TRUE(declared) << declared.error().to_string() << "\n" << declared.error().details;
  auto frame = plugin::compose_frame_graph(*declared);
  ASSERT_TRUE(frame) << frame.error().to_string();
  graph::ParameterSet params(frame->parameters);
  auto plan = graph::compile(*frame, techniques().library.declarations(), params, {1920, 1080, 2048});
  ASSERT_TRUE(plan) << plugin::errors_to_error(plan.errors()).details;
  const std::string text = graph::to_text(*plan);
  const std::string golden = std::string(PENUMBRA_TEST_DATA_DIR) + "/golden/techniques/" + name + ".txt";
  const char* update = std::getenv("PENUMBRA_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    std::ofstream(golden, std::ios::binary) << text;
    GTEST_SKIP() << "updated " << golden;
  }
  const std::string expected = read_file(golden);
  ASSERT_FALSE(expected.empty()) << golden << " missing; run with PENUMBRA_UPDATE_GOLDEN=1";
  EXPECT_EQ(text, expected) << "default plan of " << name << " changed; if intended, regenerate with "
                            << "PENUMBRA_UPDATE_GOLDEN=1";
}

INSTANTIATE_TEST_SUITE_P(Shipped, TechniquePlan,
                         ::testing::Values("hard", "pcf", "pcss", "pmchss", "reference", "template"));

}  // namespace
}  // namespace penumbra
