#pragma once
// What ImGui draws outside the panel: the divider that resizes the panel, and on the viewport
// only small overlays (compare labels naming each side's technique and settings, the compare
// split's draggable divider, and a refused frame's reason). The viewport stays unobstructed.
#include <string>

#include "sandbox/controller.h"
#include "sandbox/layout.h"
#include "sandbox/ui_widgets.h"

namespace penumbra::sandbox {

// The bar between panel and viewport; dragging it changes `panel_width`.
void draw_panel_divider(int& panel_width, const Layout& layout);

// Compare labels and divider, refused-frame note. The frame is drawn at the viewport's top-left.
void draw_viewport_overlay(SandboxController& c, const Layout& layout, UiProbe& probe);

// "pcss  samples=32 kernel=\"box\"": a technique and its parameters that differ from the
// defaults ("defaults" when none do).
std::string settings_label(const technique::TechniqueSession& session);

}  // namespace penumbra::sandbox
