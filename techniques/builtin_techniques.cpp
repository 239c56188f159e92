#include "techniques/builtin_techniques.h"

#include "passes/shared_passes.h"

namespace penumbra {

void register_builtin_techniques(plugin::TechniqueRegistry& registry) {
  // Each technique folder adds one line here.
}

exec::PassLibrary make_pass_library(const plugin::TechniqueRegistry& registry) {
  exec::PassLibrary library;
  register_shared_passes(library);
  registry.register_passes(library);
  return library;
}

}  // namespace penumbra
