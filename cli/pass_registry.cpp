#include "pass_registry.h"

#include "techniques/builtin_techniques.h"

namespace penumbra::cli {

Result<exec::PassLibrary> cli_pass_library(const std::vector<std::string>& plugin_dirs) {
  technique::TechniqueRegistry techniques;
  if (Status s = register_all_techniques(techniques, plugin_dirs); !s) return s.error();
  return make_pass_library(techniques);
}

}  // namespace penumbra::cli
