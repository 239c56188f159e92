#pragma once
// The sandbox's technique plugins, reloaded when one is rebuilt. Falcor's Mogwai reloads its
// render-pass libraries the same way: the old code is unloaded only once nothing runs it.
//
//   PluginReloader plugins;                  // before the registry: unloads after everything
//   technique::TechniqueRegistry registry;      // that runs plugin code is gone
//   register_builtin_techniques(registry);
//   if (Status s = plugins.load(dirs, registry); !s) fail(s);
//   exec::PassLibrary library = make_pass_library(registry);
//   SandboxController controller(registry, library);
//   controller.set_reload_hook([&] { plugins.poll(controller, registry, library); });
//
// Each plugin is loaded from a private copy of its .so (removed once mapped), never from the
// watched file: a rebuild or a `cp` over that file cannot change code that is running, and the
// new build can be loaded while the old one still runs. When a watched file's modification time
// or size changes, poll() loads the new build; if it loads and its graphs parse, the
// controller's sessions are rebuilt around the swap (same technique and parameter values where
// they still exist: SandboxController::rebuild_sessions) and the old build is unloaded. If it
// does not, the old build keeps running and the error is shown (controller.message()); the
// file is tried again when it changes again.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "sandbox/controller.h"
#include "plugin/plugin_library.h"

namespace penumbra::sandbox {

class PluginReloader {
 public:
  PluginReloader();
  ~PluginReloader();
  PluginReloader(const PluginReloader&) = delete;
  PluginReloader& operator=(const PluginReloader&) = delete;

  // Loads every plugin of plugin::plugin_search_path(dirs) into `registry` (after the
  // built-ins: a plugin of the same name replaces one). The first refusal is returned, naming
  // the file (exit 2, as on the CLI).
  Status load(const std::vector<std::string>& dirs, technique::TechniqueRegistry& registry);

  // Reloads every plugin whose file changed since it was last tried; `registry` and `library`
  // are the ones `controller` was made with. Returns how many were swapped in.
  int poll(SandboxController& controller, technique::TechniqueRegistry& registry, exec::PassLibrary& library);

  // The watched files, and the error of each one's last failed load ("" when the build in use
  // is the newest).
  struct PluginState {
    std::filesystem::path file;
    std::vector<std::string> techniques;  // what the build in use registered
    std::string error;
  };
  std::vector<PluginState> plugins() const;

 private:
  struct Plugin;
  Status reload(Plugin& p, SandboxController& controller, technique::TechniqueRegistry& registry,
                exec::PassLibrary& library);

  std::filesystem::path copies_;  // private copies of the builds being loaded
  int copy_count_ = 0;
  std::vector<std::unique_ptr<Plugin>> plugins_;
};

}  // namespace penumbra::sandbox
