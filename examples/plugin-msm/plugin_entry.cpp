// The plugin's entry points (plugin/plugin_api.h): the ABI version and the registration.
#include "msm_technique.h"
#include "plugin/plugin_api.h"

PENUMBRA_PLUGIN(msm::register_technique)
