// The pass types `penumbra graph` compiles against: the generic declarations used by the
// examples in docs/graph-examples, then every real pass type (shared passes and every
// built-in technique's own), which replace generic ones of the same name.
#include "graph/generic_pass_types.h"
#include "pass_registry.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::cli {

const graph::PassTypeRegistry& cli_pass_registry() {
  static const graph::PassTypeRegistry registry = [] {
    graph::PassTypeRegistry r;
    graph::register_generic_pass_types(r);
    plugin::TechniqueRegistry techniques;
    register_builtin_techniques(techniques);
    exec::PassLibrary library = make_pass_library(techniques);
    for (const std::string& name : library.declarations().names())
      r.add(*library.declarations().find(name));
    return r;
  }();
  return registry;
}

}  // namespace penumbra::cli
