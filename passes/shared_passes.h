#pragma once
// The pass types every frame and most techniques use (one folder each under passes/).
#include "exec/pass.h"
#include "technique/technique.h"

namespace penumbra {

void register_shared_passes(exec::PassLibrary& library);

// The pass library a session runs on: the shared passes plus every registered technique's own
// pass types (built-ins and plugins alike).
exec::PassLibrary make_pass_library(const technique::TechniqueRegistry& registry);

// technique::load_technique_graph with the pass types of make_pass_library(registry): a technique's
// graph with its exposed parameters described, for code that has a registry but no library.
Result<graph::GraphDesc> load_technique_graph(const technique::TechniqueRegistry& registry,
                                              const technique::Technique& technique);

}  // namespace penumbra
