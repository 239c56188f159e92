#pragma once
#include "technique/technique.h"

namespace penumbra::baseline {
void register_techniques(technique::TechniqueRegistry& registry);
}
