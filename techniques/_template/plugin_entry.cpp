// Shared-library plugin entry points (plugin/plugin_api.h): the ABI version this plugin was
// built against and the function that registers its technique. Not needed for a built-in
// (delete it then). See docs/writing-a-technique.md.
#include "plugin/plugin_api.h"
#include "techniques/_template/template_technique.h"

PENUMBRA_PLUGIN(penumbra::template_technique::register_technique)
