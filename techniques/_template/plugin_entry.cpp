// Shared-library plugin entry point: build this file with template_technique.cpp as a MODULE
// library, put the .so in a directory given to plugin::load_plugin_directory or
// `penumbra techniques --plugin-dir DIR`. Not needed for a built-in (delete it then).
// See docs/writing-a-technique.md.
#include "techniques/_template/template_technique.h"

extern "C" void penumbra_register_plugin(penumbra::plugin::TechniqueRegistry& registry) {
  penumbra::template_technique::register_technique(registry);
}
