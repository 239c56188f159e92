// The sandbox reloads a rebuilt plugin (sandbox/plugin_reload.h), under OSMesa without a window: the
// test plays the rebuild by copying the other build of tests/plugin's reload_probe plugin over
// the watched .so. The new build runs with the parameter values that still exist; a build that
// fails to load leaves the old one running and its error shown.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "sandbox/controller.h"
#include "sandbox/plugin_reload.h"
#include "techniques/builtin_techniques.h"
#include "test_support/gl_context.h"
#include "test_support/temp_dir.h"

namespace penumbra::sandbox {
namespace {

namespace fs = std::filesystem;

const fs::path kPlugins = PENUMBRA_TEST_PLUGIN_ROOT;

struct PluginReload : ::testing::Test {
  void SetUp() override {
    test::gl_context();
    dir = test::fresh_temp_dir("plugin_reload");
    install(kPlugins / "reload_build1" / "reload_probe.so");
    register_builtin_techniques(registry);
    Status loaded = plugins.load({dir.string()}, registry);
    ASSERT_TRUE(loaded) << loaded.error().to_string();
    library = make_pass_library(registry);
    controller = std::make_unique<SandboxController>(registry, library);
    ASSERT_TRUE(controller->session().set_shadow_size(256));
    Status s = controller->init("ball", "reload_probe", 32, 24);
    ASSERT_TRUE(s) << s.error().to_string();
  }
  void TearDown() override {
    controller.reset();
    fs::remove_all(dir);
  }

  // "Rebuilds" the plugin: `so` replaces the watched reload_probe.so (both builds' graphs stay
  // beside it), dated later than the build it replaces.
  void install(const fs::path& so) {
    for (int build : {1, 2}) {
      const fs::path graph = kPlugins / ("reload_build" + std::to_string(build)) / "reload_probe";
      fs::create_directories(dir / "reload_probe");
      fs::copy(graph, dir / "reload_probe", fs::copy_options::overwrite_existing | fs::copy_options::recursive);
    }
    const fs::path watched = dir / "reload_probe.so";
    fs::copy_file(so, watched, fs::copy_options::overwrite_existing);
    fs::last_write_time(watched, fs::file_time_type::clock::now() + std::chrono::seconds(++installs));
  }
  int poll() { return plugins.poll(*controller, registry, library); }

  // The one value the probe fills its mask with (it fails the test when the mask is not uniform).
  float mask_value() {
    Status s = controller->render_frame();
    EXPECT_TRUE(s) << s.error().to_string();
    std::vector<float> m = controller->session().executor().resource("shadow_mask")->read();
    const auto [lo, hi] = std::minmax_element(m.begin(), m.end());
    EXPECT_EQ(*lo, *hi);
    return *lo;
  }

  fs::path dir;
  int installs = 0;
  PluginReloader plugins;  // before the registry: unloads after everything running plugin code
  technique::TechniqueRegistry registry;
  exec::PassLibrary library;
  std::unique_ptr<SandboxController> controller;
};

TEST_F(PluginReload, ARebuiltPluginRunsWithTheParameterValuesThatStillExist) {
  ASSERT_TRUE(controller->set_param("level", "0.75"));
  ASSERT_TRUE(controller->set_param("only_in_build_1", "7"));
  EXPECT_NEAR(mask_value(), 0.75f, 1e-3f);

  install(kPlugins / "reload_build2" / "reload_probe.so");
  EXPECT_EQ(poll(), 1);
  EXPECT_EQ(controller->message(), "");
  EXPECT_EQ(controller->session().technique(), "reload_probe");
  const graph::ParameterSet& p = controller->session().params();
  EXPECT_DOUBLE_EQ(p.get_real("level"), 0.75) << "kept";
  EXPECT_EQ(p.find("only_in_build_1"), nullptr) << "gone with build 1";
  ASSERT_NE(p.find("only_in_build_2"), nullptr);
  EXPECT_EQ(p.get_int("only_in_build_2"), 3) << "new: its default";
  EXPECT_NEAR(mask_value(), 0.375f, 1e-3f) << "build 2 halves the level";
  EXPECT_EQ(poll(), 0) << "unchanged since";
}

TEST_F(PluginReload, ABuildThatFailsToLoadLeavesTheOldOneRunningAndShowsWhy) {
  ASSERT_TRUE(controller->set_param("level", "0.5"));
  const std::string watched = (dir / "reload_probe.so").string();

  std::ofstream(dir / "half_written.so") << "a linker still writing";
  install(dir / "half_written.so");
  EXPECT_EQ(poll(), 0);
  EXPECT_NE(controller->message().find(watched), std::string::npos) << controller->message();
  EXPECT_NE(controller->message().find("previous build keeps running"), std::string::npos) << controller->message();
  EXPECT_NEAR(mask_value(), 0.5f, 1e-3f) << "build 1 still runs";
  EXPECT_EQ(plugins.plugins().at(0).error.empty(), false);

  install(kPlugins / "wrong_abi" / "wrong_abi.so");
  EXPECT_EQ(poll(), 0);
  EXPECT_NE(controller->message().find("plugin ABI version " + std::to_string(plugin::kPluginAbiVersion + 1)),
            std::string::npos) << controller->message();
  EXPECT_NEAR(mask_value(), 0.5f, 1e-3f);

  install(kPlugins / "reload_build2" / "reload_probe.so");  // fixed: the next change loads
  EXPECT_EQ(poll(), 1);
  EXPECT_TRUE(plugins.plugins().at(0).error.empty());
  EXPECT_NEAR(mask_value(), 0.25f, 1e-3f);
}

TEST_F(PluginReload, TheControllerPollsFromItsFrames) {
  controller->set_reload_hook([&] { poll(); });
  install(kPlugins / "reload_build2" / "reload_probe.so");
  std::this_thread::sleep_for(std::chrono::milliseconds(600));  // the hook runs every ~0.5 s
  ASSERT_TRUE(controller->render_frame());
  EXPECT_NE(controller->session().params().find("only_in_build_2"), nullptr);
  EXPECT_NEAR(mask_value(), 0.25f, 1e-3f);
}

}  // namespace
}  // namespace penumbra::sandbox
