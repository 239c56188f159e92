// sspcss: screen-space percentage-closer soft shadows (MohammadBagher, Kautz, Holzschuch,
// Soler). The graph (sspcss.json) chooses the separable or the Poisson filters through
// `enabled`; this file only registers the pass types.
#include "techniques/sspcss/sspcss_technique.h"

#include "techniques/sspcss/passes/sspcss_pass_types.h"

namespace penumbra::sspcss {

namespace {
void register_passes(exec::PassLibrary& library) {
  library.add(prepare_pass_type());
  library.add(blocker_search_x_pass_type());
  library.add(blocker_search_y_pass_type());
  library.add(blocker_search_poisson_pass_type());
  library.add(filter_x_pass_type());
  library.add(filter_y_pass_type());
  library.add(filter_poisson_pass_type());
}
}  // namespace

void register_technique(technique::TechniqueRegistry& registry) {
  registry.add({.name = "sspcss",
                .graph_file = "techniques/sspcss/sspcss.json",
                .register_passes = register_passes});
}

}  // namespace penumbra::sspcss
