#pragma once
// The techniques linked into every Penumbra binary. make_pass_library() (the pass library they
// run on) is libpenumbra's, declared in passes/shared_passes.h.
#include "passes/shared_passes.h"
#include "plugin/technique.h"

namespace penumbra {

// Adds every built-in technique (baseline, reference, pmchss, ...) to `registry`.
void register_builtin_techniques(plugin::TechniqueRegistry& registry);

}  // namespace penumbra
