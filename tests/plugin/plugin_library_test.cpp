// Loading technique plugins (plugin/plugin_library.h): a plugin linking libpenumbra loads and
// renders with its graph and shader read from beside its .so; a plugin of another ABI version,
// a library without the entry points and a file that is no library are refused with a message
// naming the file (and both versions); the search path is --plugin-dir, then
// PENUMBRA_PLUGIN_PATH.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "gl/shader_files.h"
#include "plugin/plugin_file_check.h"
#include "plugin/plugin_library.h"
#include "techniques/builtin_techniques.h"
#include "test_support/technique_rig.h"
#include "test_support/temp_dir.h"

namespace penumbra::test {
namespace {

namespace fs = std::filesystem;

std::string plugin_dir(const std::string& name) { return std::string(PENUMBRA_TEST_PLUGIN_ROOT) + "/" + name; }
std::string plugin_file(const std::string& dir, const std::string& name) { return plugin_dir(dir) + "/" + name + ".so"; }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(PluginLibrary, TheTemplateAsAPluginRendersItsHardShadow) {
  TechniqueRig rig({.width = 64, .height = 48, .technique = "template", .techniques = register_builtin_techniques,
                    .plugin_dirs = {plugin_dir("template")}});
  ASSERT_NE(rig.registry().find("template"), nullptr);
  rig.set_scene(builtin_scene("ball"));
  rig.render();
  const metrics::MaskImage mask = rig.shadow_mask();
  ASSERT_EQ(mask.pixels.size(), 64u * 48u);
  const auto shadowed = std::count(mask.pixels.begin(), mask.pixels.end(), 0.0f);
  const auto lit = std::count(mask.pixels.begin(), mask.pixels.end(), 1.0f);
  EXPECT_GT(shadowed, 0);
  EXPECT_GT(lit, shadowed);
  EXPECT_EQ(shadowed + lit, static_cast<long>(mask.pixels.size())) << "strength 1: a hard mask";
}

TEST(PluginLibrary, LoadingADirectoryRegistersItsPassTypesAndReadsItsFilesFromThere) {
  technique::TechniqueRegistry registry;
  Result<int> loaded = plugin::load_plugin_directory(plugin_dir("reload_build1"), registry);
  ASSERT_TRUE(loaded) << loaded.error().to_string();
  EXPECT_EQ(*loaded, 1);
  const technique::Technique* t = registry.find("reload_probe");
  ASSERT_NE(t, nullptr);
  EXPECT_NE(make_pass_library(registry).find("reload_probe_fill"), nullptr);
  // Its graph exists only beside the .so: the directory became a shader root.
  const auto on_disk = gl::ShaderFileSystem::default_instance().disk_path(t->graph_file);
  ASSERT_TRUE(on_disk);
  EXPECT_EQ(fs::canonical(*on_disk), fs::canonical(plugin_dir("reload_build1") + "/reload_probe/build1.json"));
  Result<graph::GraphDesc> g = load_technique_graph(registry, *t);
  ASSERT_TRUE(g) << g.error().to_string();
  EXPECT_EQ(g->parameters.size(), 2u);
}

TEST(PluginLibrary, AnotherAbiVersionIsRefusedNamingTheFileAndBothVersions) {
  const std::string file = plugin_file("wrong_abi", "wrong_abi");
  Result<plugin::PluginLibrary> lib = plugin::PluginLibrary::open(file);
  ASSERT_FALSE(lib);
  EXPECT_EQ(lib.error().file, file);
  EXPECT_EQ(lib.error().exit_code(), 2);
  const std::string m = lib.error().to_string();
  EXPECT_TRUE(contains(m, "plugin ABI version " + std::to_string(plugin::kPluginAbiVersion + 1))) << m;
  EXPECT_TRUE(contains(m, "this Penumbra's is " + std::to_string(plugin::kPluginAbiVersion))) << m;
}

TEST(PluginLibrary, ALibraryWithoutTheEntryPointsIsRefused) {
  const std::string file = plugin_file("no_entry", "no_entry");
  Result<plugin::PluginLibrary> lib = plugin::PluginLibrary::open(file);
  ASSERT_FALSE(lib);
  EXPECT_EQ(lib.error().file, file);
  EXPECT_TRUE(contains(lib.error().message, "not a Penumbra plugin")) << lib.error().message;
  EXPECT_TRUE(contains(lib.error().message, "PENUMBRA_PLUGIN")) << lib.error().message;
}

TEST(PluginLibrary, AFileThatIsNoLibraryIsRefused) {
  const fs::path dir = fresh_temp_dir("plugin_not_a_library");
  std::ofstream(dir / "text.so") << "not an ELF file\n";
  technique::TechniqueRegistry registry;
  Result<int> loaded = plugin::load_plugin_directory(dir.string(), registry);
  ASSERT_FALSE(loaded);
  EXPECT_EQ(loaded.error().file, (dir / "text.so").string());
  EXPECT_TRUE(contains(loaded.error().message, "cannot load plugin")) << loaded.error().message;
  fs::remove_all(dir);
}

// PENUMBRA_PLUGIN's section is what the host reads before dlopen.
TEST(PluginFile, TheAbiVersionIsReadFromTheFileWithoutLoadingIt) {
  Result<int> abi = plugin::read_plugin_abi_version(plugin_file("template", "template"));
  ASSERT_TRUE(abi) << abi.error().to_string();
  EXPECT_EQ(*abi, plugin::kPluginAbiVersion);
  // wrong_abi's static constructor aborts: reading its version must not run it.
  Result<int> wrong = plugin::read_plugin_abi_version(plugin_file("wrong_abi", "wrong_abi"));
  ASSERT_TRUE(wrong) << wrong.error().to_string();
  EXPECT_EQ(*wrong, plugin::kPluginAbiVersion + 1);
}

// A half-written .so would be mapped past its end and fault (SIGBUS) on first touch: each cut
// is refused by name before dlopen, whichever part of the file it removed.
TEST(PluginFile, ATruncatedLibraryIsRefusedBeforeItIsMapped) {
  const fs::path dir = fresh_temp_dir("plugin_truncated");
  const fs::path whole = plugin_file("template", "template");
  const auto size = fs::file_size(whole);
  for (const auto keep : {size - 1, size - 200, size / 2, size / 10, decltype(size){100}}) {
    SCOPED_TRACE("kept " + std::to_string(keep) + " of " + std::to_string(size) + " bytes");
    const fs::path cut = dir / "template.so";
    fs::copy_file(whole, cut, fs::copy_options::overwrite_existing);
    fs::resize_file(cut, keep);
    Result<plugin::PluginLibrary> lib = plugin::PluginLibrary::open(cut);
    ASSERT_FALSE(lib);
    EXPECT_EQ(lib.error().file, cut.string());
    EXPECT_EQ(lib.error().exit_code(), 2);
    EXPECT_TRUE(contains(lib.error().message, "truncated or damaged")) << lib.error().message;
  }
  fs::remove_all(dir);
}

TEST(PluginLibrary, AMissingDirectoryIsBadInput) {
  technique::TechniqueRegistry registry;
  Result<int> loaded = plugin::load_plugins({plugin_dir("no_such_directory")}, registry);
  ASSERT_FALSE(loaded);
  EXPECT_EQ(loaded.error().file, plugin_dir("no_such_directory"));
  EXPECT_EQ(loaded.error().exit_code(), 2);
}

TEST(PluginSearchPath, OptionsComeFirstThenTheEnvironmentsEntries) {
  ::setenv("PENUMBRA_PLUGIN_PATH", "/a::/b:", 1);
  EXPECT_EQ(plugin::plugin_search_path({"x", "y"}), (std::vector<std::string>{"x", "y", "/a", "/b"}));
  ::unsetenv("PENUMBRA_PLUGIN_PATH");
  EXPECT_EQ(plugin::plugin_search_path({"x"}), (std::vector<std::string>{"x"}));
}

}  // namespace
}  // namespace penumbra::test
