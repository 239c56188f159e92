#pragma once
// Variance Shadow Maps (Donnelly & Lauritzen, "Variance Shadow Maps", I3D 2006): the shadow
// map's light distances and their squares are box-filtered, and a receiver's visibility is the
// one-sided Chebyshev bound P(x >= t) <= s^2 / (s^2 + (t - mean)^2).
#include "exec/pass.h"
#include "technique/technique.h"

namespace vsm {

// "vsm_moments": shadow map (window depth) -> RG32F (mean, mean of squares) of the light
// distance over a (2r+1)^2 box, r = blur_radius texels (compute).
penumbra::exec::PassType moments_pass_type();
// "vsm_mask": G-buffer view depth + moments -> shadow_mask by the Chebyshev bound (compute).
penumbra::exec::PassType mask_pass_type();

// Adds technique "vsm" (graph vsm/vsm.json, found beside the plugin's .so) and both pass types.
void register_technique(penumbra::technique::TechniqueRegistry& registry);

}  // namespace vsm
