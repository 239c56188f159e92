#pragma once
// Command line of penumbra-sandbox (GL-free, unit-tested):
//   penumbra-sandbox [--scene NAME|FILE] [--technique T] [--size WxH] [--shadow-size N]
//                    [--script FILE] [--screenshot OUT.png] [--context glfw|osmesa|egl]
//                    [--camera C] [--light-dir X,Y,Z] [--light-size S] [--ground on|off]
//                    [--write-exhaustive-script FILE [--screenshot-dir DIR]] [--plugin-dir DIR]...
//                    [--max-fps N] [--state-file FILE]
// The scene options are the CLI's (cli/options/scene_option.h), so a frame is staged alike.
#include <optional>
#include <string>
#include <vector>

#include "scene/cascades.h"
#include "scene/staging.h"
#include "util/error.h"

namespace penumbra::sandbox {

struct SandboxOptions {
  std::string scene = "showcase";
  std::string technique;  // empty: the first registered
  int width = 1280, height = 800;  // pixels
  std::optional<int> shadow_size;  // texels
  scene::CascadeSettings cascades;  // --cascades, --cascade-split, --cascade-blend, --cascade-tint
  std::string script;
  std::string screenshot;
  std::string context;  // empty: glfw
  std::string exhaustive_script;  // tool mode: write the generated test script and exit
  std::string screenshot_dir = ".";
  scene::StagingOptions staging;  // --camera, --light-dir, --light-size, --ground (the initial scene)
  int max_fps = 0;          // 0: no cap
  std::string state_file;   // rewritten every frame (sandbox/ui_state_dump.h)
  std::vector<std::string> plugin_dirs;  // then PENUMBRA_PLUGIN_PATH; reloaded when rebuilt
  bool help = false;
};

Result<SandboxOptions> parse_sandbox_options(const std::vector<std::string>& argv);
std::string sandbox_help();

}  // namespace penumbra::sandbox
