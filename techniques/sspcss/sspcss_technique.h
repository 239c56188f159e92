#pragma once
#include "technique/technique.h"

namespace penumbra::sspcss {
// Adds the "sspcss" technique (graph techniques/sspcss/sspcss.json) and its pass types.
void register_technique(technique::TechniqueRegistry& registry);
}  // namespace penumbra::sspcss
