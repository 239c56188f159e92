#pragma once
// --scene NAME|FILE.gltf shared by render, eval and bench: a built-in name or a glTF path.
#include <string>

#include "scene/scene.h"
#include "util/error.h"

namespace penumbra::cli {

Result<scene::Scene> load_scene_option(const std::string& name_or_path);

}  // namespace penumbra::cli
