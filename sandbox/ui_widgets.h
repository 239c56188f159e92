#pragma once
// The panel's widget helpers: combos that report themselves, tooltips that wrap, and the probe
// through which tests that drive the real window with X events find widgets and what is open
// (--state-file, sandbox/ui_state_dump.h). Needs an ImGui frame.
#include <array>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>

#include <imgui.h>

#include "sandbox/display.h"

namespace penumbra::sandbox {

// Where widgets are and what is open, filled while the panel is drawn. Rects are window pixels
// {x, y, w, h}, origin top-left.
struct UiProbe {
  using Rect = std::array<float, 4>;
  std::map<std::string, Rect> items;   // widgets by probe id (the label; "reset:NAME" per parameter)
  std::set<std::string> combos;        // probe ids of combos
  std::string open_popup;              // the combo whose list is open ("" none)
  std::optional<Rect> popup, tooltip;  // the open combo list's and the tooltip's windows
  std::map<std::string, int> keys;     // shortcut keys acted on: "space", "f12", "escape"
  std::map<std::string, std::string> texts;  // readouts drawn over the view this frame ("penumbra")
  std::string active;                  // the probed widget being edited or held this frame ("" none)
  void begin_frame() {
    texts.clear();
    active.clear();
    open_popup.clear();
    popup.reset();
    tooltip.reset();
  }
};

// Records the last item's rect under `id`.
void probe_item(UiProbe& probe, const std::string& id);
// ImGui::BeginCombo that records itself (its rect while closed, its list's window while open).
bool begin_combo(UiProbe& probe, const char* label, const char* preview, int flags = 0);
// An entry of an open combo's list, recorded as "COMBO/TEXT" (tests click list entries).
bool selectable(UiProbe& probe, const char* combo, const std::string& text, bool selected);
// A combo over fixed choices; true when the choice changed.
bool combo_index(UiProbe& probe, const char* label, int* current, std::initializer_list<const char*> choices);
// A tooltip for the last item, wrapped so it fits beside the cursor in the window.
void item_tooltip(const std::string& text);
// The same for a region the caller tests itself (drawn shapes).
void wrapped_tooltip(const std::string& text);
// Records the tooltip window of this frame, if one is open (call after the last widget).
void probe_tooltip(UiProbe& probe);

// A colour map's gradient, left (t = 0) to right (t = 1), as the display draws it: the legends
// of the resource viewer and of the compare error view.
void draw_colour_bar(ImDrawList* dl, ImVec2 at, ImVec2 size, ViewerSettings::Map map);

}  // namespace penumbra::sandbox
