// pmchss: penumbra-mask contact-hardening soft shadows (Sterna 2018). The graph (pmchss.json)
// selects the variant (regular / penumbra_mask / min_filter), mask resolution, blur, max filter
// and checkerboard through `enabled` conditions; this file only registers the pass types.
#include "techniques/pmchss/pmchss_technique.h"

#include "techniques/pmchss/passes/pmchss_pass_types.h"

namespace penumbra::pmchss {

namespace {
void register_passes(exec::PassLibrary& library) {
  library.add(penumbra_mask_pass_type());
  library.add(min_downsample_pass_type());
  library.add(shadow_mask_pass_type());
  library.add(checker_upsample_pass_type());
}
}  // namespace

void register_technique(technique::TechniqueRegistry& registry) {
  registry.add({.name = "pmchss",
                .graph_file = "techniques/pmchss/pmchss.json",
                .register_passes = register_passes});
}

}  // namespace penumbra::pmchss
