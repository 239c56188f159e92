#pragma once
// Parameter presets: a technique's parameter values saved as JSON,
//   {"technique": "pcss", "parameters": {"samples": 32, "use_blur": false}}
// Loading is all-or-nothing: a preset written for another technique, or naming a parameter the
// technique does not have, or holding a value out of range, is rejected and changes nothing.
// GL-free (unit-tested without a window). Shipped presets live beside a technique's graph:
// techniques/baseline/pcss.json -> techniques/baseline/presets/pcss.<preset>.json (`paper`: the
// paper's constants).
//
//   std::string text = format_preset("pcss", session.params());
//   Result<Preset> p = parse_preset(text, "presets/soft.json");
//   Result<graph::ParameterSet> next = preset_applied(*p, "pcss", session.params());
#include <string>
#include <vector>

#include "graph/parameters.h"
#include "util/error.h"

namespace penumbra::technique {

struct Technique;

struct Preset {
  std::string technique;
  std::string parameters_json;  // the "parameters" object, as JSON text
};

std::string format_preset(const std::string& technique, const graph::ParameterSet& params);
// Checks the shape only; `source` names the file in errors.
Result<Preset> parse_preset(const std::string& text, const std::string& source);
// The parameter set with the preset applied; an error (and no change) when the preset is for
// another technique or any key/value does not fit.
Result<graph::ParameterSet> preset_applied(const Preset& preset, const std::string& technique,
                                           const graph::ParameterSet& current);

// Names of the presets shipped with a technique (embedded at build time, or files beside a
// plugin's graph), sorted.
std::vector<std::string> shipped_presets(const Technique& technique);
// A shipped preset of a technique (read through the shader file system: embedded in installed
// binaries), or a preset file when `name` is a path (contains '/' or ends in .json). The error
// lists the shipped presets when none matches.
Result<Preset> load_preset(const Technique& technique, const std::string& name);

}  // namespace penumbra::technique
