// The out-of-tree examples (examples/plugin-vsm, examples/plugin-msm) as a user builds them:
// `cmake --install` of this build to a temporary prefix, each example configured in a folder of
// its own with find_package(Penumbra) against that prefix and built, its own tests run (ctest:
// msm's compare it with the installed built-in techniques and ray-traced reference), then the
// INSTALLED `penumbra` and `penumbra-sandbox` load them with --plugin-dir: parameters listed, a
// soft shadow rendered, eval's row, the sandbox's scripted mode.
// One process (not one per test case): the install and the builds happen once, in main().
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

fs::path g_work;      // prefix/, build-NAME/ and outputs, under the temp folder
fs::path g_prefix;
fs::path g_plugins;   // the vsm example's plugin directory
fs::path g_msm_plugins;

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
    CommandRun install = run_command(shell_quote(PENUMBRA_CMAKE) + " --install " + shell_quote(PENUMBRA_BUILD_DIR) +
                                     " --prefix " + q(g_prefix));
    ASSERT_EQ(install.exit_code, 0) << install.output;
    g_plugins = build_example("vsm", vsm_ctest);
    g_msm_plugins = build_example("msm", msm_ctest);
  }
  // Configures and builds examples/plugin-NAME against the prefix, runs its ctest; its plugins/.
  static fs::path build_example(const std::string& name, CommandRun& ctest) {
    const fs::path build = g_work / ("build-" + name);
    const std::string cmake = shell_quote(PENUMBRA_CMAKE);
    const fs::path source = fs::path(PENUMBRA_EXAMPLES_DIR) / ("plugin-" + name);
    CommandRun configure = run_command(cmake + " -G Ninja -S " + q(source) + " -B " + q(build) +
                                       " -DCMAKE_BUILD_TYPE=" PENUMBRA_BUILD_TYPE " -DCMAKE_PREFIX_PATH=" + q(g_prefix));
    EXPECT_EQ(configure.exit_code, 0) << configure.output;
    CommandRun compile = run_command(cmake + " --build " + q(build) + " -j 2");
    EXPECT_EQ(compile.exit_code, 0) << compile.output;
    EXPECT_TRUE(fs::exists(build / "plugins" / (name + ".so")));
    EXPECT_TRUE(fs::exists(build / "plugins" / name / (name + ".json"))) << "the graph beside the .so";
    ctest = run_command(shell_quote(PENUMBRA_CTEST) + " --test-dir " + q(build) + " --output-on-failure");
    return build / "plugins";
  }
  void TearDown() override {
    if (!::testing::UnitTest::GetInstance()->Failed()) fs::remove_all(g_work);  // kept to look at
  }
  static inline CommandRun vsm_ctest, msm_ctest;
};

TEST(OutOfTreeExample, ItsOwnTestsPassAgainstTheInstalledTestSupport) {
  for (const CommandRun* run : {&ExampleEnvironment::vsm_ctest, &ExampleEnvironment::msm_ctest}) {
    EXPECT_EQ(run->exit_code, 0) << run->output;
    EXPECT_TRUE(contains(run->output, "100% tests passed")) << run->output;
  }
}

// The installed `penumbra render` of the ball with a plugin's technique: an umbra, lit ground and
// a penumbra between.
void expect_soft_shadow(const fs::path& plugins, const std::string& technique_and_settings, const std::string& png) {
  const fs::path mask = g_work / png;
  CommandRun r = installed("penumbra", "render --context osmesa --plugin-dir " + q(plugins) + " --technique " +
                                           technique_and_settings + " --scene ball --size 96x64 --shadow-size 512 --mask " +
                                           q(mask));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const sandbox_test::ImageStats s = sandbox_test::png_stats(mask.string());
  ASSERT_TRUE(s.loaded);
  EXPECT_GT(s.dark, 0.005) << "the ball's umbra";
  EXPECT_GT(s.bright, 0.5) << "lit ground";
  EXPECT_LT(s.dark + s.bright, 1.0) << "some penumbra between";
}

TEST(OutOfTreeExample, TheMomentShadowMapRendersASoftShadowFromTheInstalledCli) {
  CommandRun list = installed("penumbra", "techniques msm --json --plugin-dir " + q(g_msm_plugins));
  ASSERT_EQ(list.exit_code, 0) << list.output;
  EXPECT_TRUE(contains(list.output, "moment_format")) << list.output;
  expect_soft_shadow(g_msm_plugins, "msm --set moment_format=RGBA16", "msm_mask.png");
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
  expect_soft_shadow(g_plugins, "vsm --set blur_radius=4", "vsm_mask.png");
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
