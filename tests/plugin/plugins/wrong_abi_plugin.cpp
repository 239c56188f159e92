// A plugin built against another plugin ABI (one more than this Penumbra's): the host must refuse
// it, naming this file and both versions, before any of its code runs: neither its register
// function nor a static constructor (dlopen would run it: the ABI is read from the file first).
#include <cstdlib>

#include "plugin/plugin_api.h"

// What PENUMBRA_PLUGIN emits, with the other version: the host reads this before dlopen.
PENUMBRA_PLUGIN_ABI_NOTE(3)
static_assert(PENUMBRA_PLUGIN_ABI_VERSION + 1 == 3, "the note's version is this ABI's plus one");

extern "C" __attribute__((visibility("default"))) int penumbra_plugin_abi_version() {
  return PENUMBRA_PLUGIN_ABI_VERSION + 1;
}

extern "C" __attribute__((visibility("default"))) void penumbra_register_plugin(
    penumbra::technique::TechniqueRegistry&) {
  std::abort();  // a host that calls this fails the test loudly
}

__attribute__((constructor)) static void runs_at_dlopen() {
  std::abort();  // a host that dlopens this before reading its ABI version dies here
}
