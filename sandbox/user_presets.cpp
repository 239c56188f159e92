#include "sandbox/user_presets.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <system_error>

namespace penumbra::sandbox {

namespace fs = std::filesystem;

fs::path user_preset_dir() {
  if (const char* d = std::getenv("PENUMBRA_PRESET_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return fs::path(x) / "penumbra" / "presets";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".config" / "penumbra" / "presets";
  return fs::path(".penumbra-presets");
}

std::vector<std::string> user_presets(const fs::path& dir, const std::string& technique) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir / technique, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".json" && it->is_regular_file(ec)) names.push_back(it->path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

Result<fs::path> user_preset_path(const fs::path& dir, const std::string& technique, const std::string& name) {
  const bool plain = !name.empty() && name.size() <= 64 && name.front() != '.' &&
                     std::all_of(name.begin(), name.end(), [](unsigned char c) {
                       return std::isalnum(c) || c == '_' || c == '-' || c == '.';
                     });
  if (!plain)
    return make_error("preset name '" + shortened(name) + "' must be 1-64 letters, digits, '_', '-' or '.' (not starting with '.')");
  return dir / technique / (name + ".json");
}

}  // namespace penumbra::sandbox
