#pragma once
// Parameter presets: a technique's parameter values saved as JSON,
//   {"technique": "pcss", "parameters": {"samples": 32, "use_blur": false}}
// Loading is all-or-nothing: a preset written for another technique, or naming a parameter the
// technique does not have, or holding a value of the wrong type or out of range, is rejected
// and changes nothing. The text goes through util/json_text.h's checks (nesting, numbers, keys
// given twice) before it is parsed. GL-free: fuzzed by tests/fuzz/fuzz_preset.cpp.
#include <string>

#include "graph/parameters.h"
#include "util/error.h"

namespace penumbra::graph {

struct Preset {
  std::string technique;
  std::string parameters_json;  // the "parameters" object, as JSON text
};

std::string format_preset(const std::string& technique, const ParameterSet& params);
// Checks the shape only; `source` names the file in errors.
Result<Preset> parse_preset(const std::string& text, const std::string& source);
// The parameter set with the preset applied; an error (and no change) when the preset is for
// another technique or any key/value does not fit.
Result<ParameterSet> preset_applied(const Preset& preset, const std::string& technique, const ParameterSet& current);

}  // namespace penumbra::graph
