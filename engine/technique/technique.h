#pragma once
// A shadow technique is a plugin: a name, a graph description (JSON, with its parameters
// described once inside it) and the pass types of its own. Every technique writes the same
// contract, a screen-size `shadow_mask` (1 = lit, 0 = umbra), which the frame's shared
// lighting pass consumes (frame_graph.h).
//
//   registry.add({.name = "pcss",
//                 .graph_file = "techniques/baseline/pcss.json",
//                 .register_passes = register_pcss_passes});
//
// The technique's description and parameters are in its graph JSON only ("description",
// "parameters"): the CLI and the sandbox read them from there.
//
// graph_file is relative to a shader root and read through the shader file system: a built-in's
// comes from the source tree in development and from the embedded copy in a bundled binary; a
// plugin's from beside its .so (the plugin's folder is a root).
#include <functional>
#include <string>
#include <vector>

#include "exec/pass.h"
#include "graph/graph_desc.h"
#include "util/error.h"

namespace penumbra::technique {

struct Technique {
  std::string name;
  std::string graph_file;
  std::function<void(exec::PassLibrary&)> register_passes;  // may be empty
};

class TechniqueRegistry {
 public:
  // A second technique of the same name replaces the first (a plugin may override a built-in).
  void add(Technique technique);
  // Removes the technique of that name; false when there is none (a plugin being unloaded).
  bool remove(const std::string& name);
  const Technique* find(const std::string& name) const;
  std::vector<std::string> names() const;  // registration order
  const std::vector<Technique>& all() const { return techniques_; }
  // Registers every technique's own pass types into `library`.
  void register_passes(exec::PassLibrary& library) const;

 private:
  std::vector<Technique> techniques_;
};

// The technique's graph as declared in its JSON file, with its exposed parameters described by
// the pass types in `pass_types` (graph/exposures.h): what a ParameterSet is made from.
Result<graph::GraphDesc> load_technique_graph(const Technique& technique, const graph::PassTypeRegistry& pass_types);

// Shared-library plugins add techniques to a registry: plugin/plugin_library.h.

}  // namespace penumbra::technique
