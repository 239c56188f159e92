#include "pass_registry.h"

#include "techniques/builtin_techniques.h"

namespace penumbra::cli {

const graph::PassTypeRegistry& cli_pass_registry() {
  static const exec::PassLibrary library = [] {
    plugin::TechniqueRegistry techniques;
    register_builtin_techniques(techniques);
    return make_pass_library(techniques);
  }();
  return library.declarations();
}

}  // namespace penumbra::cli
