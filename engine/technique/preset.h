#pragma once
// Parameter presets of a technique: the JSON format and applying one (graph/parameter_preset.h,
// GL-free and fuzzed), and where a technique's shipped presets live: beside its graph,
// techniques/baseline/pcss.json -> techniques/baseline/presets/pcss.<preset>.json (`paper`: the
// paper's constants).
//
//   std::string text = format_preset("pcss", session.params());
//   Result<Preset> p = parse_preset(text, "presets/soft.json");
//   Result<graph::ParameterSet> next = preset_applied(*p, "pcss", session.params());
#include <string>
#include <vector>

#include "graph/parameter_preset.h"
#include "util/error.h"

namespace penumbra::technique {

struct Technique;

using graph::format_preset;
using graph::parse_preset;
using graph::Preset;
using graph::preset_applied;

// Names of the presets shipped with a technique (embedded at build time, or files beside a
// plugin's graph), sorted.
std::vector<std::string> shipped_presets(const Technique& technique);
// A shipped preset of a technique (read through the shader file system: embedded in installed
// binaries), or a preset file when `name` is a path (contains '/' or ends in .json). The error
// lists the shipped presets when none matches.
Result<Preset> load_preset(const Technique& technique, const std::string& name);
// Whether load_preset reads `name` as a file path rather than a shipped preset's name.
bool is_preset_path(const std::string& name);

}  // namespace penumbra::technique
