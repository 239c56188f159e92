#pragma once
#include "plugin/technique.h"

namespace penumbra::esm {
// Adds the "esm" technique (graph techniques/esm/esm.json) and its pass types.
void register_technique(plugin::TechniqueRegistry& registry);
}  // namespace penumbra::esm
