#pragma once
// Moment Shadow Mapping (Peters & Klein, "Moment Shadow Mapping", I3D 2015): each shadow-map
// texel stores four moments of the light depth, the map is filtered like a texture, and a
// receiver's shadow is the Hamburger 4MSM bound from the filtered moments. Built on Penumbra's
// shared passes: a light-view pass with this plugin's fragment shader writes the moments,
// separable_filter blurs them, one compute pass of its own reconstructs. With a second, wider
// filter of the moments, the blockers' height above each receiver (from the moments) picks the
// width between the two: contact hardening, this example's addition (README.md).
#include "exec/pass.h"
#include "technique/technique.h"

namespace msm {

// "msm_moments": the casters from the light into `moments` (RGBA16 or RGBA32F) and `depth`.
penumbra::exec::PassType moments_pass_type();
// "msm_mask": G-buffer view depth + filtered moments (and the wider-filtered `moments_wide`,
// optional) -> shadow_mask (compute).
penumbra::exec::PassType mask_pass_type();

// Adds technique "msm" (graph msm/msm.json beside the plugin's .so) and both pass types.
void register_technique(penumbra::technique::TechniqueRegistry& registry);

}  // namespace msm
