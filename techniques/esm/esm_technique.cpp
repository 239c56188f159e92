// esm: extended shadow maps (Bujnak 2004), anti-aliased hard shadows from silhouette edge
// distances. The graph (esm.json) switches the quads (comparison mode), the two-pass fallback
// and the debug views through `enabled` conditions; this file only registers the pass types.
#include "techniques/esm/esm_technique.h"

#include "techniques/esm/passes/esm_pass_types.h"

namespace penumbra::esm {

namespace {
void register_passes(exec::PassLibrary& library) {
  library.add(depth_pass_type());
  library.add(silhouette_quad_pass_type());
  library.add(mask_pass_type());
  library.add(debug_pass_type());
}
}  // namespace

void register_technique(technique::TechniqueRegistry& registry) {
  registry.add({.name = "esm",
                .graph_file = "techniques/esm/esm.json",
                .register_passes = register_passes});
}

}  // namespace penumbra::esm
