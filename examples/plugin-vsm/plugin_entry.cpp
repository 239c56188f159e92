// The plugin's entry points (plugin/plugin_api.h): the ABI version it was built against and the
// function that registers its technique. The host refuses a build of another ABI version.
#include "plugin/plugin_api.h"
#include "vsm_technique.h"

PENUMBRA_PLUGIN(vsm::register_technique)
