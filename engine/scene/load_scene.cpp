#include "scene/load_scene.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "scene/builtin_scenes.h"
#include "scene/gltf_loader.h"

namespace penumbra::scene {
namespace {

// "k=v,k=v" after a built-in name's ':' -> its parameter overrides.
Result<ProceduralParams> parse_overrides(const std::string& name, const std::string& text) {
  ProceduralParams params;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      return make_error("'" + item + "' in '" + name + ":" + text + "' is not k=v (a parameter of the built-in scene)");
    const std::string value = item.substr(eq + 1);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
      return make_error("'" + value + "' for '" + item.substr(0, eq) + "' of scene '" + name + "' is not a number");
    params[item.substr(0, eq)] = static_cast<float>(v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return params;
}

}  // namespace

Result<Scene> load_scene(const std::string& name_or_path) {
  const std::string ext = std::filesystem::path(name_or_path).extension().string();
  if (ext == ".gltf" || ext == ".glb") return load_gltf(name_or_path);
  const size_t colon = name_or_path.find(':');
  const std::string name = name_or_path.substr(0, colon);
  ProceduralParams overrides;
  if (colon != std::string::npos) {
    Result<ProceduralParams> parsed = parse_overrides(name, name_or_path.substr(colon + 1));
    if (!parsed) return parsed.error();
    overrides = *parsed;
  }
  Result<Scene> builtin = make_builtin_scene(name, overrides);
  if (builtin) return builtin;
  Error e = builtin.error();
  if (e.message.rfind("unknown built-in scene", 0) == 0)
    e.message = "'" + name_or_path + "' is neither a .gltf/.glb file nor a built-in scene: " + e.message;
  return e;
}

}  // namespace penumbra::scene
