// The out-of-tree example (examples/plugin-vsm) as a user builds it: `cmake --install` of this
// build to a temporary prefix, the example configured in a folder of its own with
// find_package(Penumbra) against that prefix and built, its own test run (ctest), then the
// INSTALLED `penumbra` and `penumbra-sandbox` load it with --plugin-dir: its parameters are
// listed, it renders a soft shadow, eval has its row, the sandbox's scripted mode renders it.
// One process (not one per test case): the install and the build happen once, in main().
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "sandbox/image_stats.h"
#include "test_support/run_command.h"
#include "test_support/temp_dir.h"

namespace penumbra::test {
namespace {

namespace fs = std::filesystem;

fs::path g_work;      // prefix/, build/ and outputs, under the temp folder
fs::path g_prefix;
fs::path g_plugins;   // the example's plugin directory

std::string q(const fs::path& p) { return shell_quote(p.string()); }
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

CommandRun installed(const std::string& tool, const std::string& args) {
  return run_command(q(g_prefix / "bin" / tool) + " " + args);
}

class ExampleEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    g_work = fresh_temp_dir("plugin_example");
    g_prefix = g_work / "prefix";
    const fs::path build = g_work / "build";
    g_plugins = build / "plugins";
    const std::string cmake = shell_quote(PENUMBRA_CMAKE);
    CommandRun install = run_command(cmake + " --install " + shell_quote(PENUMBRA_BUILD_DIR) + " --prefix " + q(g_prefix));
    ASSERT_EQ(install.exit_code, 0) << install.output;
    CommandRun configure = run_command(cmake + " -G Ninja -S " + shell_quote(PENUMBRA_EXAMPLE_SOURCE) + " -B " + q(build) +
                                       " -DCMAKE_BUILD_TYPE=" PENUMBRA_BUILD_TYPE " -DCMAKE_PREFIX_PATH=" + q(g_prefix));
    ASSERT_EQ(configure.exit_code, 0) << configure.output;
    CommandRun compile = run_command(cmake + " --build " + q(build) + " -j 2");
    ASSERT_EQ(compile.exit_code, 0) << compile.output;
    ASSERT_TRUE(fs::exists(g_plugins / "vsm.so"));
    ASSERT_TRUE(fs::exists(g_plugins / "vsm" / "vsm.json")) << "the graph beside the .so";
    ctest = run_command(shell_quote(PENUMBRA_CTEST) + " --test-dir " + q(build) + " --output-on-failure");
  }
  void TearDown() override {
    if (!::testing::UnitTest::GetInstance()->Failed()) fs::remove_all(g_work);  // kept to look at
  }
  static inline CommandRun ctest;
};

TEST(OutOfTreeExample, ItsOwnTestsPassAgainstTheInstalledTestSupport) {
  EXPECT_EQ(ExampleEnvironment::ctest.exit_code, 0) << ExampleEnvironment::ctest.output;
  EXPECT_TRUE(contains(ExampleEnvironment::ctest.output, "100% tests passed")) << ExampleEnvironment::ctest.output;
}

TEST(OutOfTreeExample, TechniquesListsItsParameters) {
  CommandRun r = installed("penumbra", "techniques vsm --json --plugin-dir " + q(g_plugins));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json list = nlohmann::json::parse(r.output, nullptr, false);
  ASSERT_TRUE(list.is_array() && list.size() == 1u) << r.output;
  std::vector<std::string> names;
  for (const auto& p : list[0]["parameters"]) names.push_back(p["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"blur_radius", "min_variance", "light_bleeding"}));

  CommandRun env = run_command("PENUMBRA_PLUGIN_PATH=" + q(g_plugins) + " " + q(g_prefix / "bin" / "penumbra") +
                               " techniques vsm");
  EXPECT_EQ(env.exit_code, 0) << env.output;
}

TEST(OutOfTreeExample, RenderWritesASoftShadow) {
  const fs::path mask = g_work / "vsm_mask.png";
  CommandRun r = installed("penumbra", "render --context osmesa --plugin-dir " + q(g_plugins) +
                                           " --technique vsm --set blur_radius=4 --scene ball --size 96x64"
                                           " --shadow-size 512 --mask " + q(mask));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const sandbox_test::ImageStats s = sandbox_test::png_stats(mask.string());
  ASSERT_TRUE(s.loaded);
  EXPECT_GT(s.dark, 0.005) << "the ball's umbra";
  EXPECT_GT(s.bright, 0.5) << "lit ground";
  EXPECT_LT(s.dark + s.bright, 1.0) << "some penumbra between";
}

TEST(OutOfTreeExample, EvalHasItsRow) {
  const fs::path json = g_work / "eval.json";
  CommandRun r = installed("penumbra", "eval --context osmesa --plugin-dir " + q(g_plugins) +
                                           " --scene ball --techniques vsm,hard --size 48x32 --shadow-size 512"
                                           " --rays 4 --frames 1 --json " + q(json));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(json);
  const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
  ASSERT_TRUE(report.contains("rows")) << r.output;
  ASSERT_EQ(report["rows"].size(), 2u);
  EXPECT_EQ(report["rows"][0]["technique"], "vsm");
  const double rmse = report["rows"][0]["rmse"];
  EXPECT_GE(rmse, 0.0);
  EXPECT_LT(rmse, 0.5) << "a shadow of the ball, not noise";
}

TEST(OutOfTreeExample, TheSandboxScriptedModeRendersIt) {
  const fs::path script = g_work / "vsm.json", shot = g_work / "sandbox_vsm.png";
  std::ofstream(script) << R"([{"scene": "ball"}, {"technique": "vsm"}, {"set": {"blur_radius": 3}},)"
                        << R"( {"wait": 2}, {"screenshot": )" << nlohmann::json(shot.string()).dump() << "}]";
  CommandRun r = installed("penumbra-sandbox", "--context osmesa --size 96x64 --shadow-size 512 --plugin-dir " +
                                                   q(g_plugins) + " --script " + q(script));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const sandbox_test::ImageStats s = sandbox_test::png_stats(shot.string());
  ASSERT_TRUE(s.loaded) << r.output;
  EXPECT_GT(s.variance, 10.0) << "a lit scene with a shadow, not a blank frame";
}

}  // namespace
}  // namespace penumbra::test

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ::testing::AddGlobalTestEnvironment(new penumbra::test::ExampleEnvironment);
  return RUN_ALL_TESTS();
}
