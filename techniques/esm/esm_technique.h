#pragma once
#include "technique/technique.h"

namespace penumbra::esm {
// Adds the "esm" technique (graph techniques/esm/esm.json) and its pass types.
void register_technique(technique::TechniqueRegistry& registry);
}  // namespace penumbra::esm
