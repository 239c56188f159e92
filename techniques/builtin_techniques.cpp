#include "techniques/builtin_techniques.h"

#include "plugin/plugin_library.h"

#include "techniques/baseline/baseline_techniques.h"
#include "techniques/esm/esm_technique.h"
#include "techniques/mpg/mpg_technique.h"
#include "techniques/pmchss/pmchss_technique.h"
#include "techniques/reference/reference_technique.h"
#include "techniques/sspcss/sspcss_technique.h"

namespace penumbra {

void register_builtin_techniques(technique::TechniqueRegistry& registry) {
  // Each technique folder adds one line here.
  baseline::register_techniques(registry);
  esm::register_technique(registry);
  mpg::register_technique(registry);
  pmchss::register_technique(registry);
  reference::register_techniques(registry);
  sspcss::register_technique(registry);
}

Status register_all_techniques(technique::TechniqueRegistry& registry, const std::vector<std::string>& plugin_dirs) {
  register_builtin_techniques(registry);
  if (Result<int> loaded = plugin::load_plugins(plugin_dirs, registry); !loaded) return loaded.error();
  return {};
}

}  // namespace penumbra
