#include "cli/scene_option.h"

#include "scene/load_scene.h"

namespace penumbra::cli {

Result<scene::Scene> load_scene_option(const std::string& name_or_path) {
  return scene::load_scene(name_or_path);
}

}  // namespace penumbra::cli
