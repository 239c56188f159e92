// A plugin built against another plugin ABI (one more than this Penumbra's): the host must refuse
// it, naming this file and both versions, and never call its register function.
#include <cstdlib>

#include "plugin/plugin_api.h"

extern "C" __attribute__((visibility("default"))) int penumbra_plugin_abi_version() {
  return PENUMBRA_PLUGIN_ABI_VERSION + 1;
}

extern "C" __attribute__((visibility("default"))) void penumbra_register_plugin(
    penumbra::technique::TechniqueRegistry&) {
  std::abort();  // a host that calls this fails the test loudly
}
