#pragma once
#include "plugin/technique.h"

namespace penumbra::pmchss {
// Adds the "pmchss" technique (graph techniques/pmchss/pmchss.json) and its pass types.
void register_technique(plugin::TechniqueRegistry& registry);
}  // namespace penumbra::pmchss
