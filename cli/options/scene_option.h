#pragma once
// The scene options render, eval and bench share (and penumbra-sandbox takes too), so a frame
// seen in the sandbox can be reproduced from the command line:
//   --scene NAME|FILE.gltf        a built-in name or a glTF path
//   --camera scene|fit|file[:N|:NAME]|X,Y,Z:TX,TY,TZ
//   --light-dir X,Y,Z             light -> scene direction
//   --light-size S                emitter diameter, world units (0 = hard)
//   --ground on|off               a plane under models that have no floor (default on)
// They are staged by scene::stage_scene (engine/scene/staging.h).
//
//   const std::vector<OptionSpec> kSpecs = with_scene_options({{"scene", ...}, ...});
//   auto scene = load_scene_option(*args->get("scene"), *args, width, height);
#include <string>
#include <vector>

#include "cli/options/args.h"
#include "scene/scene.h"
#include "scene/staging.h"
#include "util/error.h"

namespace penumbra::cli {

struct SceneOptions {
  scene::StagingOptions staging;
};

// --scene NAME|FILE, its help naming the built-in scenes.
OptionSpec scene_name_option();
// --camera, --light-dir, --light-size, --ground, for a command's option table.
std::vector<OptionSpec> scene_option_specs();
std::vector<OptionSpec> with_scene_options(std::vector<OptionSpec> specs);

// Errors name the option and the expected form (exit code 2).
Result<SceneOptions> parse_scene_options(const ParsedArgs& args);
Result<scene::CameraChoice> parse_camera_choice(const std::string& text);
Result<glm::vec3> parse_vec3(const std::string& option, const std::string& text);

// Loads and stages `name_or_path` for a frame of width x height (the aspect of a fitted camera).
Result<scene::Scene> load_scene_option(const std::string& name_or_path, const SceneOptions& options, int width,
                                       int height);
Result<scene::Scene> load_scene_option(const std::string& name_or_path, const ParsedArgs& args, int width,
                                       int height);
// With the default options (fitted camera for 16:9, the ground plane on).
Result<scene::Scene> load_scene_option(const std::string& name_or_path);

// The --camera / --light-dir / --light-size / --ground arguments that reproduce this camera and
// light exactly (a pose, not "fit"), e.g. for the sandbox's "reproduce" line.
std::string scene_options_text(const scene::Camera& camera, const scene::Light& light, bool ground);

}  // namespace penumbra::cli
