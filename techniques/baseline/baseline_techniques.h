#pragma once
#include "plugin/technique.h"

namespace penumbra::baseline {
void register_techniques(plugin::TechniqueRegistry& registry);
}
