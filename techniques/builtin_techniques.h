#pragma once
// The techniques linked into every Penumbra binary, and the pass library they run on.
#include "exec/pass.h"
#include "plugin/technique.h"

namespace penumbra {

// Adds every built-in technique (baseline, reference, pmchss, ...) to `registry`.
void register_builtin_techniques(plugin::TechniqueRegistry& registry);

// The shared frame passes (passes/) plus every registered technique's own pass types.
exec::PassLibrary make_pass_library(const plugin::TechniqueRegistry& registry);

}  // namespace penumbra
