#pragma once
// The pass types `penumbra graph` compiles graph files against: the shared passes, every
// built-in technique's own and those of the plugins in `plugin_dirs` and PENUMBRA_PLUGIN_PATH.
#include <string>
#include <vector>

#include "exec/pass.h"
#include "util/error.h"

namespace penumbra::cli {

// Errors name the plugin file or directory that failed (bad input).
Result<exec::PassLibrary> cli_pass_library(const std::vector<std::string>& plugin_dirs);

}  // namespace penumbra::cli
