#pragma once
// What the host checks in a plugin file before dlopen maps it or runs any of its code:
//   - the ELF header is a shared library for this machine (64-bit, this byte order and CPU);
//   - the program headers, every segment and the section headers lie inside the file (a
//     half-written or truncated .so would be mapped past its end and fault with SIGBUS on the
//     first touch of a missing page);
//   - the ABI version the plugin was built against, read from the section that PENUMBRA_PLUGIN
//     emits (plugin/plugin_api.h): a plugin of another ABI is refused before its static
//     constructors could run against mismatched types.
//
//   Result<int> abi = read_plugin_abi_version(file);   // Error naming the file and the reason
#include <filesystem>

#include "util/error.h"

namespace penumbra::plugin {

Result<int> read_plugin_abi_version(const std::filesystem::path& file);

}  // namespace penumbra::plugin
