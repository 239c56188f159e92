#pragma once
// The `reference` technique plugin: graph reference.json, pass types reference_raster and
// reference_raytraced. Registered by techniques/builtin_techniques.cpp.
#include "technique/technique.h"

namespace penumbra::reference {
void register_techniques(technique::TechniqueRegistry& registry);
}
