#pragma once
// The interactive host: a GLFW window, Dear ImGui, camera input, and the frame loop that also
// runs scripts (same controller calls as the widgets). Returns the process exit code.
#include <optional>
#include <string>
#include <vector>

#include "sandbox/controller.h"
#include "sandbox/script.h"
#include "gl/context.h"

namespace penumbra::sandbox {

struct WindowRun {
  std::optional<std::vector<ScriptStep>> script;  // run it, then exit
  std::string final_screenshot;                   // saved after the script (or after 3 frames)
  int max_fps = 0;                                // 0: no cap
  std::string state_file;                         // rewritten every frame (ui_state_dump.h)
};

int run_window(gl::Context& context, SandboxController& controller, const WindowRun& run);

}  // namespace penumbra::sandbox
