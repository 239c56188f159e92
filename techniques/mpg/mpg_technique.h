#pragma once
#include "technique/technique.h"

namespace penumbra::mpg {
// Adds the "mpg" technique (graph techniques/mpg/mpg.json) and its pass types.
void register_technique(technique::TechniqueRegistry& registry);
}  // namespace penumbra::mpg
