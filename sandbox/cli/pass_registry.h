#pragma once
// The pass type declarations the CLI compiles graph files against (the lead implements this
// with the real pass types; pass_registry_stub.cpp is a temporary stand-in).
#include "graph/pass_types.h"

namespace penumbra::cli {

const graph::PassTypeRegistry& cli_pass_registry();

}  // namespace penumbra::cli
