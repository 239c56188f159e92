// The baselines are graphs of shared pass types (passes/), so they register no pass code:
//   hard  passes/hard_mask          one comparison per pixel
//   pcf   passes/pcf_mask           fixed-width box or Vogel-disk PCF
//   pcss  passes/pcss               blocker search + Fernando 2005 eq. 1 + PCF
// Descriptions and parameters live in each technique's JSON (the one description).
#include "techniques/baseline/baseline_techniques.h"

namespace penumbra::baseline {

void register_techniques(technique::TechniqueRegistry& registry) {
  registry.add({.name = "hard",
                .graph_file = "techniques/baseline/hard.json"});
  registry.add({.name = "pcf",
                .graph_file = "techniques/baseline/pcf.json"});
  registry.add({.name = "pcss",
                .graph_file = "techniques/baseline/pcss.json"});
}

}  // namespace penumbra::baseline
