#include "sandbox/ui_widgets.h"

#include <imgui.h>
#include <imgui_internal.h>

#include "metrics/heat_map.h"

namespace penumbra::sandbox {

namespace {
UiProbe::Rect rect_of(ImVec2 min, ImVec2 max) { return {min.x, min.y, max.x - min.x, max.y - min.y}; }
}  // namespace

void probe_item(UiProbe& probe, const std::string& id) {
  probe.items[id] = rect_of(ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
  if (ImGui::IsItemActive()) probe.active = id;
}

bool begin_combo(UiProbe& probe, const char* label, const char* preview, int flags) {
  probe.combos.insert(label);
  const bool open = ImGui::BeginCombo(label, preview, flags);
  if (!open) {
    probe_item(probe, label);  // while open, the last item is the list's window, not the combo
    return false;
  }
  probe.open_popup = label;
  const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  probe.popup = UiProbe::Rect{at.x, at.y, size.x, size.y};
  return true;
}

bool selectable(UiProbe& probe, const char* combo, const std::string& text, bool selected) {
  const bool clicked = ImGui::Selectable(text.c_str(), selected);
  if (ImGui::IsItemVisible()) probe_item(probe, std::string(combo) + "/" + text);  // not scrolled out of the list
  return clicked;
}

bool combo_index(UiProbe& probe, const char* label, int* current, std::initializer_list<const char*> choices) {
  int i = 0;
  const char* shown = "";
  for (const char* c : choices)
    if (i++ == *current) shown = c;
  if (!begin_combo(probe, label, shown)) return false;
  bool changed = false;
  i = 0;
  for (const char* c : choices) {
    if (selectable(probe, label, c, i == *current) && i != *current) {
      *current = i;
      changed = true;
    }
    ++i;
  }
  ImGui::EndCombo();
  return changed;
}

void wrapped_tooltip(const std::string& text) {
  if (text.empty()) return;
  ImGui::BeginTooltip();
  // About 40 characters a line: long explanations stay narrow enough to fit beside the cursor.
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
  ImGui::TextUnformatted(text.c_str());
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

void item_tooltip(const std::string& text) {
  if (!text.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) wrapped_tooltip(text);
}

void probe_tooltip(UiProbe& probe) {
  for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
    if ((w->Flags & ImGuiWindowFlags_Tooltip) && w->Active) probe.tooltip = UiProbe::Rect{w->Pos.x, w->Pos.y, w->Size.x, w->Size.y};
}

void draw_colour_bar(ImDrawList* dl, ImVec2 at, ImVec2 size, ViewerSettings::Map map) {
  auto colour = [&](float t) -> ImU32 {
    glm::vec3 c(t);
    if (map == ViewerSettings::Map::heat) c = glm::vec3(metrics::heat_color(t)) / 255.0f;
    if (map == ViewerSettings::Map::signed_error) c = diverging_color(t);
    return ImGui::GetColorU32(ImVec4(c.r, c.g, c.b, 1.0f));
  };
  constexpr int kSteps = 32;
  for (int i = 0; i < kSteps; ++i) {
    const float t0 = float(i) / kSteps, t1 = float(i + 1) / kSteps;
    dl->AddRectFilledMultiColor(ImVec2(at.x + t0 * size.x, at.y), ImVec2(at.x + t1 * size.x, at.y + size.y), colour(t0),
                                colour(t1), colour(t1), colour(t0));
  }
}

}  // namespace penumbra::sandbox
