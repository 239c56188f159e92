#pragma once
// The techniques linked into every Penumbra binary. make_pass_library() (the pass library they
// run on) is libpenumbra's, declared in passes/shared_passes.h.
#include <string>
#include <vector>

#include "passes/shared_passes.h"
#include "technique/technique.h"
#include "util/error.h"

namespace penumbra {

// Adds every built-in technique (baseline, reference, pmchss, ...) to `registry`.
void register_builtin_techniques(technique::TechniqueRegistry& registry);

// What every command and the sandbox offer: the built-ins, then the plugins of `plugin_dirs`
// (--plugin-dir) and PENUMBRA_PLUGIN_PATH (plugin/plugin_library.h); a plugin of the same name
// replaces a built-in. Errors name the plugin file or directory (bad input, exit 2).
Status register_all_techniques(technique::TechniqueRegistry& registry, const std::vector<std::string>& plugin_dirs);

}  // namespace penumbra
