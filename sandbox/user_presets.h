#pragma once
// Presets the user saves from the sandbox, kept per technique in a folder of their own so the
// preset menu can list them beside the shipped ones (GL-free, unit-tested):
//   $PENUMBRA_PRESET_DIR, else $XDG_CONFIG_HOME/penumbra/presets, else ~/.config/penumbra/presets
//   <dir>/<technique>/<name>.json
#include <filesystem>
#include <string>
#include <vector>

#include "util/error.h"

namespace penumbra::sandbox {

std::filesystem::path user_preset_dir();
// Names of the presets saved for `technique` in `dir`, sorted.
std::vector<std::string> user_presets(const std::filesystem::path& dir, const std::string& technique);
// Where a preset called `name` is saved; an error when the name is empty or not a plain file
// name (letters, digits, '_', '-', '.'; no leading '.').
Result<std::filesystem::path> user_preset_path(const std::filesystem::path& dir, const std::string& technique,
                                               const std::string& name);

}  // namespace penumbra::sandbox
