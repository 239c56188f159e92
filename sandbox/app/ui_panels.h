#pragma once
// The ImGui panels. Every widget calls a SandboxController method (the same ones script steps
// call); the only state kept here is what the user is typing.
#include <string>

#include "app/controller.h"

namespace penumbra::sandbox {

struct UiState {
  char scene_path[512] = "";
  char preset_path[512] = "preset.json";
  char screenshot_path[512] = "penumbra-screenshot.png";
  bool screenshot_requested = false;  // set by the button, served by the host after rendering
  std::string host_message;           // e.g. "saved penumbra-screenshot.png"
};

void draw_sandbox_ui(SandboxController& controller, UiState& ui);

}  // namespace penumbra::sandbox
