// Golden plan dumps of the documented example graphs: to_text(compile(example)) must equal
// tests/graph/golden/<name>.txt. After an intended change, regenerate with
//   PENUMBRA_UPDATE_GOLDEN=1 ./graph_tests --gtest_filter='GraphGolden*'
// and review the diff like code.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "graph/graph_json.h"
#include "test_registry.h"

namespace penumbra::graph {
namespace {

using namespace testing;

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class GraphGolden : public ::testing::TestWithParam<const char*> {};

TEST_P(GraphGolden, PlanMatchesGoldenDump) {
  const std::string name = GetParam();
  const std::string example = std::string(PENUMBRA_SOURCE_DIR) + "/docs/graph-examples/" + name + ".json";
  const std::string golden = std::string(PENUMBRA_TEST_DATA_DIR) + "/golden/" + name + ".txt";
  auto graph = load_graph_json(example);
  ASSERT_TRUE(graph) << all_messages(graph.errors());
  ParameterSet params(graph->parameters);
  auto plan = compile(*graph, generic_registry(), params, {1920, 1080, 2048});
  ASSERT_TRUE(plan) << all_messages(plan.errors());
  const std::string text = to_text(*plan);
  const char* update = std::getenv("PENUMBRA_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    std::ofstream(golden, std::ios::binary) << text;
    GTEST_SKIP() << "updated " << golden;
  }
  const std::string expected = read_file(golden);
  ASSERT_FALSE(expected.empty()) << golden << " missing; run with PENUMBRA_UPDATE_GOLDEN=1";
  EXPECT_EQ(text, expected) << "plan of " << example << " changed; if intended, regenerate with "
                            << "PENUMBRA_UPDATE_GOLDEN=1";
}

INSTANTIATE_TEST_SUITE_P(Examples, GraphGolden,
                         ::testing::Values("pcss", "tiled_penumbra", "progressive_reference"));

}  // namespace
}  // namespace penumbra::graph
