#pragma once
// --plugin-dir DIR, shared by every command that takes techniques (techniques, render, eval,
// bench, graph) and by penumbra-sandbox. The directories given, then PENUMBRA_PLUGIN_PATH, are
// loaded by register_all_techniques() (techniques/builtin_techniques.h) or, in the sandbox, by
// its plugin reloader. GL-free: the sandbox's option model includes it.
#include "cli/options/args.h"

namespace penumbra::cli {

inline OptionSpec plugin_dir_option_spec() {
  return {"plugin-dir", true, true, "DIR",
          "also load technique plugins (*.so, their graph and shaders beside them) from DIR; "
          "then from PENUMBRA_PLUGIN_PATH (colon-separated)"};
}

}  // namespace penumbra::cli
