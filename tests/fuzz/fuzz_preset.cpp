// Parameter presets through what `--techniques t@FILE` and the sandbox's preset menu run: the
// text checks, the parser and applying the preset to a parameter set of every type (bool, int,
// float, choice; structural and ranged).
#include <cstddef>
#include <cstdint>
#include <string>

#include "graph/graph_json.h"
#include "graph/parameter_preset.h"

namespace {

const penumbra::graph::ParameterSet& parameters() {
  static const penumbra::graph::ParameterSet set = [] {
    auto g = penumbra::graph::parse_graph_json(R"({"name": "fuzz",
      "parameters": [
        {"name": "samples", "type": "int", "default": 16, "min": 1, "max": 64},
        {"name": "radius", "type": "float", "default": 0.5, "min": 0.0, "max": 4.0},
        {"name": "tiles", "type": "bool", "default": false, "structural": true},
        {"name": "kernel", "type": "choice", "default": "box", "choices": ["box", "vogel"]}],
      "passes": []})");
    return g ? penumbra::graph::ParameterSet(g->parameters) : penumbra::graph::ParameterSet();
  }();
  return set;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto preset = penumbra::graph::parse_preset(text, "fuzz.json");
  if (preset) (void)penumbra::graph::preset_applied(*preset, preset->technique, parameters());
  return 0;
}
