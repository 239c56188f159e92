// The baselines are graphs of shared pass types (passes/), so they register no pass code.
#include "techniques/baseline/baseline_techniques.h"

namespace penumbra::baseline {

void register_techniques(plugin::TechniqueRegistry& registry) {
  registry.add({.name = "hard",
                .description = "Hard shadow mapping (one comparison per pixel)",
                .graph_file = "techniques/baseline/hard.json"});
}

}  // namespace penumbra::baseline
