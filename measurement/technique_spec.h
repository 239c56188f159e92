#pragma once
// A technique with settings of its own, one item of --techniques:
//   pcss,pmchss:variant=regular,pmchss:variant=penumbra_mask:mask_divisor=2
// so one eval or bench compares variants side by side; each row is labelled by the item as
// written ("pmchss:variant=regular"). --set still applies to every listed technique that has
// the key; an item's own settings come after it and must all be its technique's parameters.
// `name@preset` starts from a shipped preset (or a preset file) instead of the defaults:
//   pmchss@paper,pmchss    the paper's constants beside the tuned defaults
#include <string>
#include <vector>

#include "technique/technique_session.h"
#include "util/error.h"

namespace penumbra::measurement {

struct TechniqueSpec {
  std::string name;               // registered technique
  std::vector<std::string> sets;  // its own "k=v"
  std::string label;              // the item as written: the row's name
  std::string preset_json = {};   // the preset's "parameters" object; empty: the defaults
};

// Parses a comma-separated list of items; every name must be registered and every own setting a
// valid value of that technique's parameter (the graph JSON is read; no GL needed).
Result<std::vector<TechniqueSpec>> parse_technique_specs(const std::string& option, const std::string& text,
                                                         const technique::TechniqueRegistry& registry);
// The technique names of `specs` (for --set key checks).
std::vector<std::string> technique_names(const std::vector<TechniqueSpec>& specs);
// Selects the spec's technique in `session`, then its preset, then the --set assignments it
// has, then its own.
Status select_technique(technique::TechniqueSession& session, const TechniqueSpec& spec,
                        const std::vector<std::string>& global_sets);

}  // namespace penumbra::measurement
