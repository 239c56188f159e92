#pragma once
// The pass type declarations `penumbra graph` compiles graph files against: every real pass
// type, the shared passes and every built-in technique's own.
#include "graph/pass_types.h"

namespace penumbra::cli {

const graph::PassTypeRegistry& cli_pass_registry();

}  // namespace penumbra::cli
