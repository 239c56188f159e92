#pragma once
// The template technique: its pass type and its registration. Rename `template` everywhere
// (folder, JSON "name", pass type, namespace) when you copy this folder.
#include "exec/pass.h"
#include "technique/technique.h"

namespace penumbra::template_technique {

// "template_mask": G-buffer view depth (position rebuilt) + shadow map -> shadow_mask (compute).
exec::PassType template_mask_pass_type();

// Adds the technique (graph techniques/_template/template.json) and its pass type.
void register_technique(technique::TechniqueRegistry& registry);

}  // namespace penumbra::template_technique
