#pragma once
// A technique of the sandbox tests' own ("sandbox_tiny"): two trivial compute pass types and a
// graph JSON that writes shadow_mask, so the sandbox is tested whatever built-ins exist.
#include "technique/technique.h"

namespace penumbra::sandbox_test {

inline constexpr const char* kTinyTechnique = "sandbox_tiny";
void register_tiny_technique(technique::TechniqueRegistry& registry);

}  // namespace penumbra::sandbox_test
