// The real sandbox window under Xvfb: xvfb-run + GLFW + ImGui + the script path. The script is
// generated from the registry at test time (--write-exhaustive-script), so every registered
// technique and every parameter's min, max and default is visited with no test change; every
// screenshot is read back (stb_image) and must not be blank. A missing xvfb-run FAILS the test.
#include <gtest/gtest.h>

#include "test_support/temp_dir.h"
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "image_stats.h"
#include "xvfb_run.h"

namespace {

namespace fs = std::filesystem;
using penumbra::sandbox_test::RunResult;
using penumbra::sandbox_test::run;
using penumbra::sandbox_test::run_in_xvfb;
using penumbra::sandbox_test::xvfb;

fs::path fresh_dir(const std::string& name) { return penumbra::test::fresh_temp_dir("sandbox_xvfb_" + name); }

// Only the right half counts: the UI panel (at most 45% of the width) must not be what makes an
// image "not blank"; the rendered scene must.
void expect_not_blank(const fs::path& png) {
  auto s = penumbra::sandbox_test::png_stats(png.string(), 0.5);
  ASSERT_TRUE(s.loaded) << "cannot read " << png;
  EXPECT_GT(s.variance, 20.0) << png << " looks blank (mean " << s.mean << ")";
}

// All registered techniques (the built-ins plus the tests' tiny one) through the real window.
TEST(SandboxXvfb, ExhaustiveScriptOverEveryTechnique) {
  const std::string x = xvfb();
  ASSERT_FALSE(x.empty()) << "xvfb-run is not installed: run scripts/setup.sh (installs xvfb)";
  fs::path dir = fresh_dir("exhaustive");
  fs::path script = dir / "exhaustive.json";
  RunResult w = run(std::string(SANDBOX_TEST_HOST) + " --write-exhaustive-script " + script.string() +
                    " --screenshot-dir " + dir.string() + " --size 400x240 --shadow-size 512");
  ASSERT_EQ(w.exit_code, 0) << w.output;

  RunResult r = run_in_xvfb(x, std::string(SANDBOX_TEST_HOST) + " --scene showcase --size 400x240 --script " + script.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("GL error"), std::string::npos) << r.output;

  int shots = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".png") {
      ++shots;
      expect_not_blank(e.path());
    }
  std::ifstream in(script);
  std::stringstream text;
  text << in.rdbuf();
  size_t expected = 0;
  for (size_t p = text.str().find("\"screenshot\""); p != std::string::npos;
       p = text.str().find("\"screenshot\"", p + 1))
    ++expected;
  EXPECT_EQ(shots, static_cast<int>(expected));
  EXPECT_GE(shots, 2);
  fs::remove_all(dir);
}

// Defect 5: scripts/run.sh, the README's main command, started a sandbox path that did not exist.
// Run against this build (PENUMBRA_BUILD_DIR skips its release build), with a display, it starts
// the sandbox on the showcase scene.
TEST(SandboxXvfb, RunScriptStartsTheSandboxWithADisplay) {
  const std::string x = xvfb();
  ASSERT_FALSE(x.empty()) << "xvfb-run is not installed: run scripts/setup.sh (installs xvfb)";
  fs::path dir = fresh_dir("run_sh");
  RunResult r = run_in_xvfb(x, "PENUMBRA_BUILD_DIR=" + std::string(PENUMBRA_BUILD_DIR) + " " + PENUMBRA_SOURCE_DIR +
                                   "/scripts/run.sh --size 320x240 --shadow-size 512 --screenshot " +
                                   (dir / "shot.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("no display"), std::string::npos) << r.output;
  expect_not_blank(dir / "shot.png");
  fs::remove_all(dir);
}

// The shipped binary itself, with only the built-in techniques (fails, saying so, if none are
// registered: the sandbox has nothing to show then).
TEST(SandboxXvfb, ShippedBinaryScreenshotIsNotBlank) {
  const std::string x = xvfb();
  ASSERT_FALSE(x.empty()) << "xvfb-run is not installed: run scripts/setup.sh (installs xvfb)";
  fs::path dir = fresh_dir("shipped");
  RunResult r = run_in_xvfb(x, std::string(SANDBOX_BINARY) + " --scene ball --size 480x320 --shadow-size 512 --screenshot " +
                    (dir / "shot.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  expect_not_blank(dir / "shot.png");
  fs::remove_all(dir);
}

// Bad scripts are rejected before a window opens: exit 2, the step index named.
TEST(SandboxCli, BadScriptNamesTheStepAndExitsTwo) {
  fs::path dir = fresh_dir("bad");
  std::ofstream(dir / "bad.json") << R"([{"wait": 1}, {"technique": "hard"}, {"teleport": true}])";
  RunResult r = run(std::string(SANDBOX_BINARY) + " --script " + (dir / "bad.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("step 2: unknown step 'teleport'"), std::string::npos) << r.output;
  RunResult h = run(std::string(SANDBOX_BINARY) + " --help");
  EXPECT_EQ(h.exit_code, 0);
  EXPECT_NE(h.output.find("--script FILE"), std::string::npos) << h.output;
  RunResult bad = run(std::string(SANDBOX_BINARY) + " --size banana");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  fs::remove_all(dir);
}

// A step that fails at run time (unknown technique) names the step; exit 2.
TEST(SandboxXvfb, RuntimeStepErrorNamesTheStep) {
  const std::string x = xvfb();
  ASSERT_FALSE(x.empty()) << "xvfb-run is not installed: run scripts/setup.sh (installs xvfb)";
  fs::path dir = fresh_dir("runtime");
  std::ofstream(dir / "s.json") << R"([{"wait": 1}, {"technique": "no_such_technique"}])";
  RunResult r = run_in_xvfb(x, std::string(SANDBOX_TEST_HOST) + " --size 160x120 --script " + (dir / "s.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("script step 1 (technique)"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

}  // namespace
