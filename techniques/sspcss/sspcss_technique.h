#pragma once
#include "plugin/technique.h"

namespace penumbra::sspcss {
// Adds the "sspcss" technique (graph techniques/sspcss/sspcss.json) and its pass types.
void register_technique(plugin::TechniqueRegistry& registry);
}  // namespace penumbra::sspcss
