#include "passes/shared_passes.h"

#include "passes/gbuffer/gbuffer_pass.h"
#include "passes/hard_mask/hard_mask_pass.h"
#include "passes/lighting/lighting_pass.h"
#include "passes/pcf_mask/pcf_mask_pass.h"
#include "passes/pcss/pcss_passes.h"
#include "passes/separable_filter/separable_filter_pass.h"
#include "passes/shadow_map/shadow_map_pass.h"
#include "passes/shadow_tiles/shadow_tiles_passes.h"
#include "passes/visualize/visualize_pass.h"

namespace penumbra {

void register_shared_passes(exec::PassLibrary& library) {
  library.add(passes::gbuffer_pass_type());
  library.add(passes::shadow_map_pass_type());
  library.add(passes::hard_mask_pass_type());
  library.add(passes::lighting_pass_type());
  library.add(passes::pcf_mask_pass_type());
  library.add(passes::pcss_blocker_search_pass_type());
  library.add(passes::pcss_filter_pass_type());
  library.add(passes::shadow_planes_pass_type());
  library.add(passes::shadow_tiles_pass_type());
  library.add(passes::separable_filter_pass_type());
  library.add(passes::visualize_pass_type());
}

exec::PassLibrary make_pass_library(const technique::TechniqueRegistry& registry) {
  exec::PassLibrary library;
  register_shared_passes(library);
  registry.register_passes(library);
  return library;
}

Result<graph::GraphDesc> load_technique_graph(const technique::TechniqueRegistry& registry,
                                              const technique::Technique& technique) {
  return technique::load_technique_graph(technique, make_pass_library(registry).declarations());
}

}  // namespace penumbra
