#pragma once
// One entry point for the CLI and sandbox: a built-in scene name or a .gltf/.glb path.
//
//   Result<Scene> s = load_scene(args.scene);   // "showcase", "ball:ball_height=1.5", "models/Fox.gltf", ...
#include <string>

#include "scene/scene.h"
#include "util/error.h"

namespace penumbra::scene {

// A name without a .gltf/.glb extension is looked up among the built-ins, its parameters at their
// defaults or as NAME:k=v,k=v sets them (builtin_scene_params); anything else is loaded as a file.
// Errors list the built-in names when neither fits, the valid keys for an unknown one.
Result<Scene> load_scene(const std::string& name_or_path);

}  // namespace penumbra::scene
