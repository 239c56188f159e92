#pragma once
// Parameter presets: a technique's parameter values saved as JSON,
//   {"technique": "pcss", "parameters": {"samples": 32, "use_blur": false}}
// Loading is all-or-nothing: a preset written for another technique, or naming a parameter the
// technique does not have, or holding a value out of range, is rejected and changes nothing.
// GL-free (unit-tested without a window).
//
//   std::string text = format_preset("pcss", session.params());
//   Result<Preset> p = parse_preset(text, "presets/soft.json");
//   Result<graph::ParameterSet> next = preset_applied(*p, "pcss", session.params());
#include <string>

#include "graph/parameters.h"
#include "util/error.h"

namespace penumbra::sandbox {

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

// File helpers; errors name the path.
Status write_text_file(const std::string& path, const std::string& text);

}  // namespace penumbra::sandbox
