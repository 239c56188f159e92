#pragma once
// The ImGui panels. Every widget calls a SandboxController method (the same ones script steps
// call); the state kept here is what the user is typing, and the probe tests read.
#include <string>

#include "sandbox/controller.h"
#include "sandbox/graph_view.h"
#include "sandbox/layout.h"
#include "sandbox/ui_widgets.h"

namespace penumbra::sandbox {

struct UiState {
  char scene_path[512] = "";
  char preset_name[64] = "my-preset";  // saved into user_preset_dir() (sandbox/user_presets.h)
  char screenshot_path[512] = "penumbra-screenshot.png";
  char metrics_path[512] = "penumbra-metrics.json";
  char save_dir[512] = ".";  // the resource viewer's "save PNG / PFM"
  SequenceSpec sequence;      // the Record frames section's choices
  char sequence_dir[512] = ".";
  bool screenshot_requested = false;  // set by the button, served by the host after rendering
  bool escape = false;                // Esc this frame: closes the topmost open thing
  bool graph_open = false;            // the Graph section (closed at start: it is tall)
  int panel_width = kDefaultPanelWidth;  // pixels; the divider drags it
  GraphViewCache graph_view;             // the plan's dot layout, redone when the plan changes
  UiProbe probe;

  // A transient note ("saved x.png"): shown for kNoteSeconds, then fades out over kFadeSeconds.
  static constexpr double kNoteSeconds = 4.0, kFadeSeconds = 1.5;
  void post(std::string text, double now) {
    note = std::move(text);
    note_time = now;
  }
  // 1 while fresh, falling to 0 as it fades; 0 when there is none.
  float note_alpha(double now) const;
  std::string note;
  double note_time = 0.0;
};

// The panel (left, full height), the divider that resizes it, and the overlays on the viewport
// (compare labels and split divider, a refused frame's reason). Nothing is drawn over the
// viewport but those overlays.
void draw_sandbox_ui(SandboxController& controller, UiState& ui, const Layout& layout);

}  // namespace penumbra::sandbox
