#pragma once
// What a technique plugin (a shared library loaded with --plugin-dir) exports. One line in one
// of its files:
//
//   PENUMBRA_PLUGIN(my_technique::register_technique)
//
// defines the two extern "C" entry points the host looks up:
//   int  penumbra_plugin_abi_version()   the PENUMBRA_PLUGIN_ABI_VERSION it was compiled against
//   void penumbra_register_plugin(penumbra::technique::TechniqueRegistry&)   adds its techniques
// and the section .penumbra_plugin_abi holding "PENUMBRA_PLUGIN_ABI=<version>", which the host
// reads from the file before dlopen (plugin/plugin_file_check.h): dlopen runs a library's static
// constructors, and a plugin of another ABI must be refused before any of its code runs.
// The host calls the register function only when both say its own version
// (plugin/plugin_library.h); a library without them, or of another version, is refused with a
// message naming the file and both versions.
#include "technique/technique.h"

// The plugin ABI: the C++ types a plugin and libpenumbra exchange (TechniqueRegistry, Technique,
// PassLibrary, PassType, PassImpl, PassContext and what they hold). Bump it with any change to
// their layout, to a virtual function or to a signature a plugin may call; a plugin built
// against another value is refused instead of crashing inside mismatched code.
#define PENUMBRA_PLUGIN_ABI_VERSION 2

namespace penumbra::plugin {

inline constexpr int kPluginAbiVersion = PENUMBRA_PLUGIN_ABI_VERSION;
inline constexpr const char* kPluginAbiVersionSymbol = "penumbra_plugin_abi_version";
inline constexpr const char* kPluginRegisterSymbol = "penumbra_register_plugin";
inline constexpr const char* kPluginAbiSection = ".penumbra_plugin_abi";
inline constexpr const char* kPluginAbiNotePrefix = "PENUMBRA_PLUGIN_ABI=";

using PluginAbiVersionFn = int (*)();
using PluginRegisterFn = void (*)(technique::TechniqueRegistry&);

}  // namespace penumbra::plugin

#define PENUMBRA_PLUGIN_STRINGIFY_(x) #x
#define PENUMBRA_PLUGIN_STRINGIFY(x) PENUMBRA_PLUGIN_STRINGIFY_(x)
// `retain` keeps the section under --gc-sections, where nothing refers to it.
#define PENUMBRA_PLUGIN_ABI_NOTE(version)                                                          \
  extern "C" __attribute__((visibility("default"), used, retain, section(".penumbra_plugin_abi"))) \
  const char penumbra_plugin_abi_note[] = "PENUMBRA_PLUGIN_ABI=" PENUMBRA_PLUGIN_STRINGIFY(version);

#define PENUMBRA_PLUGIN(register_fn)                                                           \
  PENUMBRA_PLUGIN_ABI_NOTE(PENUMBRA_PLUGIN_ABI_VERSION)                                          \
  extern "C" __attribute__((visibility("default"))) int penumbra_plugin_abi_version() {          \
    return PENUMBRA_PLUGIN_ABI_VERSION;                                                          \
  }                                                                                              \
  extern "C" __attribute__((visibility("default"))) void penumbra_register_plugin(             \
      ::penumbra::technique::TechniqueRegistry& registry) {                                         \
    register_fn(registry);                                                                       \
  }
