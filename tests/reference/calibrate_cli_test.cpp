// `penumbra calibrate` end to end (OSMesa, 64x48, 16 rays): it fits, reports fit and validation
// scenes, writes a preset that eval then loads; bad input exits 2 with the reason.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "test_support/run_command.h"
#include "test_support/temp_dir.h"

namespace penumbra::test {
namespace {

const std::string kTiny = " --context osmesa --size 64x48 --rays 16 --shadow-size 512";

CommandRun calibrate(const std::string& args) {
  return run_command(std::string(PENUMBRA_CLI) + " calibrate" + kTiny + " " + args);
}

// "ball  fit  0.1234  0.0987 ..." -> {start, fitted}
std::pair<double, double> table_row(const std::string& output, const std::string& scene, const std::string& set) {
  std::smatch m;
  const std::regex row("\n" + scene + " +" + set + " +([0-9.]+) +([0-9.]+)");
  if (!std::regex_search(output, m, row)) return {-1.0, -1.0};
  return {std::stod(m[1]), std::stod(m[2])};
}

TEST(CalibrateCli, FitsImprovesOnTheStartAndWritesALoadablePreset) {
  const auto dir = fresh_temp_dir("calibrate_cli");
  const std::string preset = (dir / "fitted.json").string();
  // The paper's constants are far from this scene's light: the fit must move them.
  CommandRun r = calibrate("--technique pmchss@paper:variant=regular --scenes ball --validate poles "
                       "--params shadow_filter_max_size --evals 8 --out " + preset);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("eval   1/8"), std::string::npos) << r.output;  // progress, one line per evaluation
  const auto [start, fitted] = table_row(r.output, "ball", "fit");
  ASSERT_GT(start, 0.0) << r.output;
  EXPECT_LT(fitted, 0.9 * start) << r.output;
  EXPECT_GT(table_row(r.output, "poles", "validate").second, 0.0) << r.output;
  EXPECT_NE(r.output.find("pcss"), std::string::npos) << "the baseline column";

  std::ifstream in(preset);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["technique"], "pmchss");
  EXPECT_EQ(j["parameters"]["variant"], "regular");
  EXPECT_EQ(j["parameters"]["penumbra_mapping"], "paper");  // from the preset it started at
  EXPECT_NE(j["parameters"]["shadow_filter_max_size"].get<double>(), 0.002);

  CommandRun e = run_command(std::string(PENUMBRA_CLI) +
                             " eval --context osmesa --scene ball --size 64x48 --rays 16 --shadow-size 512 "
                             "--frames 1 --techniques pmchss@" + preset);
  EXPECT_EQ(e.exit_code, 0) << e.output;
}

TEST(CalibrateCli, BadInputExitsTwoAndSaysWhy) {
  struct Case {
    std::string args, expected;
  };
  for (const Case& c : std::vector<Case>{
           {"--technique pmchss --scenes ball --params variant", "structural"},
           {"--technique pmchss --scenes ball --params receiver_plane_bias", "only float and int"},
           {"--technique pmchss --scenes ball --params kay", "kay"},
           {"--technique pmchss --scenes ball --params k,k", "twice"},
           {"--technique pmchss,pcss --scenes ball", "one technique"},
           {"--technique reference --scenes ball", "reference"},
           {"--technique pmchss@nope --scenes ball", "no preset 'nope'"},
           {"--technique pmchss", "--scenes"},
           {"--technique pmchss --scenes nowhere.gltf", "nowhere.gltf"},
           {"--technique pmchss --scenes ball --evals 0", "evals"},
       }) {
    CommandRun r = calibrate(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
  }
}

}  // namespace
}  // namespace penumbra::test
