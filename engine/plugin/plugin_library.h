#pragma once
// Technique plugins: shared libraries exporting the entry points of PENUMBRA_PLUGIN
// (plugin/plugin_api.h), found in plugin directories (--plugin-dir DIR, PENUMBRA_PLUGIN_PATH).
// A plugin's graph JSON and shaders lie beside its .so: loading a directory makes it a shader
// root (gl/shader_files.h), so the host never needs the plugin's sources.
//
//   technique::TechniqueRegistry registry;
//   register_builtin_techniques(registry);
//   if (Result<int> n = plugin::load_plugins({"build/plugins"}, registry); !n) fail(n.error());
#include <filesystem>
#include <string>
#include <vector>

#include "gl/dynamic_library.h"
#include "plugin/plugin_api.h"
#include "technique/technique.h"
#include "util/error.h"

namespace penumbra::plugin {

// One opened plugin. Move-only; destroying it unloads the code, so whatever the plugin
// registered (its techniques, its pass types in a PassLibrary, pass objects in an executor)
// must be gone first, as the sandbox's reload does (sandbox/plugin_reload.h).
class PluginLibrary {
 public:
  // Opens `file` and checks it: both entry points present, ABI version equal to this
  // libpenumbra's. `shown_as` names the file in errors and file() (the sandbox opens a copy of
  // the file it watches); empty = `file`. Every refusal is bad input (exit 2) naming the file;
  // an ABI mismatch names both versions.
  static Result<PluginLibrary> open(const std::filesystem::path& file,
                                    const std::filesystem::path& shown_as = {});

  // Calls the plugin's penumbra_register_plugin(registry).
  void register_into(technique::TechniqueRegistry& registry) const;
  const std::filesystem::path& file() const { return file_; }

 private:
  PluginLibrary(gl::DynamicLibrary library, std::filesystem::path file, PluginRegisterFn register_fn)
      : library_(std::move(library)), file_(std::move(file)), register_fn_(register_fn) {}

  gl::DynamicLibrary library_;
  std::filesystem::path file_;
  PluginRegisterFn register_fn_ = nullptr;
};

// The *.so files directly in `dir`, sorted by name, and `dir` made a shader root (its plugins'
// graph JSON and shaders are read from there). An error naming `dir` when it is not a directory.
Result<std::vector<std::filesystem::path>> scan_plugin_directory(const std::string& dir);

// The plugin directories in search order: `dirs` (the --plugin-dir options, in order), then the
// entries of PENUMBRA_PLUGIN_PATH (colon-separated, empty entries skipped).
std::vector<std::string> plugin_search_path(const std::vector<std::string>& dirs);

// Loads every plugin of scan_plugin_directory(dir) into `registry`, in file-name order. The
// libraries stay loaded until the process exits. Returns how many loaded; stops at
// the first refusal.
Result<int> load_plugin_directory(const std::string& dir, technique::TechniqueRegistry& registry);

// load_plugin_directory() over plugin_search_path(dirs); returns how many loaded in all.
Result<int> load_plugins(const std::vector<std::string>& dirs, technique::TechniqueRegistry& registry);

}  // namespace penumbra::plugin
