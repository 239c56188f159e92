#pragma once
#include "technique/technique.h"

namespace penumbra::pmchss {
// Adds the "pmchss" technique (graph techniques/pmchss/pmchss.json) and its pass types.
void register_technique(technique::TechniqueRegistry& registry);
}  // namespace penumbra::pmchss
