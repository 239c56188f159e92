#include "scene/load_scene.h"

#include <filesystem>

#include "scene/builtin_scenes.h"
#include "scene/gltf_loader.h"

namespace penumbra::scene {

Result<Scene> load_scene(const std::string& name_or_path) {
  const std::string ext = std::filesystem::path(name_or_path).extension().string();
  if (ext == ".gltf" || ext == ".glb") return load_gltf(name_or_path);
  Result<Scene> builtin = make_builtin_scene(name_or_path);
  if (builtin) return builtin;
  Error e = builtin.error();
  e.message = "'" + name_or_path + "' is neither a .gltf/.glb file nor a built-in scene: " + e.message;
  return e;
}

}  // namespace penumbra::scene
