// --plugin-dir DIR and PENUMBRA_PLUGIN_PATH on every command that takes techniques (techniques,
// render, eval, calibrate, bench, graph) and on penumbra-sandbox: the template plugin is listed, rendered,
// evaluated, timed, compiled and shown; a plugin of another ABI version is refused by each with
// exit code 2 and a message naming the file and both versions.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "plugin/plugin_api.h"
#include "sandbox/image_stats.h"
#include "test_support/run_command.h"
#include "test_support/temp_dir.h"

namespace penumbra::test {
namespace {

namespace fs = std::filesystem;

const std::string kTemplateDir = std::string(PENUMBRA_TEST_PLUGIN_ROOT) + "/template";
const std::string kWrongAbiDir = std::string(PENUMBRA_TEST_PLUGIN_ROOT) + "/wrong_abi";

CommandRun cli(const std::string& args) {
  return run_command(std::string(PENUMBRA_CLI) + " " + args);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(PluginCli, TechniquesListsThePluginsParameters) {
  CommandRun r = cli("techniques template --json --plugin-dir " + kTemplateDir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json list = nlohmann::json::parse(r.output, nullptr, false);
  ASSERT_TRUE(list.is_array()) << r.output;
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0]["name"], "template");
  ASSERT_EQ(list[0]["parameters"].size(), 1u);
  EXPECT_EQ(list[0]["parameters"][0]["name"], "shadow_strength");
}

TEST(PluginCli, PluginPathEnvironmentAndRepeatedOptionsAddUp) {
  const std::string reload = std::string(PENUMBRA_TEST_PLUGIN_ROOT) + "/reload_build1";
  CommandRun both = run_command("PENUMBRA_PLUGIN_PATH=" + shell_quote(reload) + " " + PENUMBRA_CLI +
                                " techniques template reload_probe --plugin-dir " + kTemplateDir);
  EXPECT_EQ(both.exit_code, 0) << both.output;
  CommandRun repeated = cli("techniques template reload_probe --plugin-dir " + kTemplateDir + " --plugin-dir " + reload);
  EXPECT_EQ(repeated.exit_code, 0) << repeated.output;
  CommandRun without = cli("techniques template");
  EXPECT_EQ(without.exit_code, 2) << without.output;
  EXPECT_TRUE(contains(without.output, "unknown technique 'template'")) << without.output;
}

TEST(PluginCli, RenderWritesThePluginsMask) {
  const fs::path dir = fresh_temp_dir("plugin_cli_render");
  const fs::path mask = dir / "mask.png";
  CommandRun r = cli("render --context osmesa --plugin-dir " + kTemplateDir +
                     " --technique template --scene ball --size 96x64 --shadow-size 512 --mask " + mask.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const sandbox_test::ImageStats s = sandbox_test::png_stats(mask.string());
  ASSERT_TRUE(s.loaded);
  EXPECT_GT(s.dark, 0.01) << "the ball's shadow";
  EXPECT_GT(s.bright, 0.5) << "lit ground";
  fs::remove_all(dir);
}

TEST(PluginCli, EvalHasAPluginRowAndBenchTimesIt) {
  const fs::path dir = fresh_temp_dir("plugin_cli_eval");
  const fs::path json = dir / "eval.json";
  CommandRun e = cli("eval --context osmesa --plugin-dir " + kTemplateDir +
                     " --scene ball --techniques template,hard --size 48x32 --shadow-size 512 --rays 4 --frames 1 --json " +
                     json.string());
  ASSERT_EQ(e.exit_code, 0) << e.output;
  std::ifstream in(json);
  const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
  ASSERT_TRUE(report.contains("rows")) << e.output;
  ASSERT_EQ(report["rows"].size(), 2u);
  EXPECT_EQ(report["rows"][0]["technique"], "template");

  CommandRun b = cli("bench --context osmesa --plugin-dir " + kTemplateDir +
                     " --techniques template --scenes ball --size 48x32 --shadow-size 256 --frames 1 --warmup 0");
  ASSERT_EQ(b.exit_code, 0) << b.output;
  EXPECT_TRUE(contains(b.output, "template_mask")) << b.output;
  fs::remove_all(dir);
}

TEST(PluginCli, GraphCompilesAgainstThePluginsPassTypes) {
  const std::string graph = std::string(PENUMBRA_SOURCE_DIR) + "/techniques/_template/template.json";
  CommandRun without = cli("graph " + graph);
  EXPECT_EQ(without.exit_code, 2) << without.output;
  EXPECT_TRUE(contains(without.output, "template_mask")) << without.output;
  CommandRun with = cli("graph " + graph + " --plugin-dir " + kTemplateDir);
  EXPECT_EQ(with.exit_code, 0) << with.output;
  CommandRun types = cli("graph --pass-types --plugin-dir " + kTemplateDir);
  EXPECT_EQ(types.exit_code, 0) << types.output;
  EXPECT_TRUE(contains(types.output, "template_mask")) << types.output;
}

#ifdef PENUMBRA_SANDBOX
TEST(PluginCli, TheSandboxShowsThePlugin) {
  const fs::path dir = fresh_temp_dir("plugin_cli_sandbox");
  const fs::path shot = dir / "shot.png";
  CommandRun r = run_command(std::string(PENUMBRA_SANDBOX) + " --context osmesa --plugin-dir " + kTemplateDir +
                             " --technique template --scene ball --size 96x64 --shadow-size 512 --screenshot " +
                             shot.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(sandbox_test::png_stats(shot.string()).loaded);
  fs::remove_all(dir);
}
#endif

// Every command refuses a plugin of another ABI version the same way: exit 2, the file, both
// versions; nothing is rendered or written.
TEST(PluginCli, EveryCommandRefusesAnotherAbiVersion) {
  const std::string so = kWrongAbiDir + "/wrong_abi.so";
  const std::string versions[] = {"plugin ABI version " + std::to_string(plugin::kPluginAbiVersion + 1),
                                  "this Penumbra's is " + std::to_string(plugin::kPluginAbiVersion)};
  std::vector<std::string> commands = {
      std::string(PENUMBRA_CLI) + " techniques",
      std::string(PENUMBRA_CLI) + " render --context osmesa --scene ball --size 32x32 --out /dev/null",
      std::string(PENUMBRA_CLI) + " eval --context osmesa --scene ball --techniques hard --size 32x32",
      std::string(PENUMBRA_CLI) + " bench --context osmesa --techniques hard --size 32x32 --frames 1",
      std::string(PENUMBRA_CLI) + " calibrate --context osmesa --technique hard --scenes ball --size 32x32",
      std::string(PENUMBRA_CLI) + " graph --pass-types",
  };
#ifdef PENUMBRA_SANDBOX
  commands.push_back(std::string(PENUMBRA_SANDBOX) + " --context osmesa --size 32x32");
#endif
  for (const std::string& command : commands) {
    SCOPED_TRACE(command);
    CommandRun r = run_command(command + " --plugin-dir " + kWrongAbiDir);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_TRUE(contains(r.output, so)) << r.output;
    for (const std::string& v : versions) EXPECT_TRUE(contains(r.output, v)) << r.output;
  }
}

// A half-copied plugin (the template's .so cut in half) is exit 2 naming it, never SIGBUS.
TEST(PluginCli, ATruncatedPluginIsRefusedByName) {
  const fs::path dir = fresh_temp_dir("plugin_cli_truncated");
  fs::copy(kTemplateDir, dir, fs::copy_options::recursive);
  const fs::path so = dir / "template.so";
  fs::resize_file(so, fs::file_size(so) / 2);
  CommandRun r = cli("techniques --plugin-dir " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(contains(r.output, so.string())) << r.output;
  EXPECT_TRUE(contains(r.output, "truncated or damaged")) << r.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace penumbra::test
