// mpg: multi-pass Gaussian contact-hardening soft shadows (Cherry & Kooima). The graph (mpg.json)
// selects the alteration (PCF / single-pass Gaussian / multi-pass Gaussian), the umbra early-out
// and the dilation through `enabled` conditions and the number of blur passes through `repeat`;
// this file only registers the pass types.
#include "techniques/mpg/mpg_technique.h"

#include "techniques/mpg/passes/mpg_pass_types.h"

namespace penumbra::mpg {

namespace {
void register_passes(exec::PassLibrary& library) {
  library.add(distance_map_pass_type());
  library.add(umbra_early_out_pass_type());
  library.add(dilate_pass_type());
  library.add(pcf_filter_pass_type());
  library.add(gaussian_filter_pass_type());
  library.add(blur_tiles_pass_type());
  library.add(multipass_blur_pass_type());
  library.add(resolve_mask_pass_type());
  library.add(distance_view_pass_type());
  library.add(penumbra_view_pass_type());
}
}  // namespace

void register_technique(technique::TechniqueRegistry& registry) {
  registry.add({.name = "mpg",
                .graph_file = "techniques/mpg/mpg.json",
                .register_passes = register_passes});
}

}  // namespace penumbra::mpg
