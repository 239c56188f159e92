#include "reference_technique.h"

#include "raster_reference_pass.h"
#include "raytraced_reference_pass.h"

namespace penumbra::reference {

void register_techniques(technique::TechniqueRegistry& registry) {
  registry.add({.name = "reference",
                .graph_file = "techniques/reference/reference.json",
                .register_passes = [](exec::PassLibrary& library) {
                  library.add(raster_reference_pass_type());
                  library.add(raytraced_reference_pass_type());
                }});
}

}  // namespace penumbra::reference
