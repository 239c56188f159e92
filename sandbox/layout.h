#pragma once
// Where the panel, the divider and the 3D viewport go in the window (GL-free, unit-tested).
// Debian's ImGui 1.86 has no docking, so the sandbox lays them out itself: the panel on the
// left at a width the user drags, a divider, and the viewport in the rest. The viewport is
// never covered by the panel, and the frame is rendered at the viewport's own size, so its
// aspect is the one the camera uses.
//
//   Layout l = compute_layout(window_w, window_h, ui.panel_width);
//   controller.resize(l.viewport.w, l.viewport.h);
namespace penumbra::sandbox {

struct Rect {
  int x = 0, y = 0, w = 0, h = 0;  // pixels, origin top-left
  bool contains(int px, int py) const { return px >= x && px < x + w && py >= y && py < y + h; }
};

inline constexpr int kMinPanelWidth = 260;    // narrower cuts the widgets' labels
inline constexpr int kDefaultPanelWidth = 400;
inline constexpr int kDividerWidth = 6;
inline constexpr int kMinViewportWidth = 64;

struct Layout {
  Rect panel, divider, viewport;
  int panel_width = 0;  // the width used (clamped)
};

// The panel keeps `panel_width` clamped to [kMinPanelWidth, window - divider - kMinViewportWidth]
// (on a window too small for both, the viewport keeps kMinViewportWidth and the panel the rest).
Layout compute_layout(int window_w, int window_h, int panel_width);

// Window width that gives a viewport `frame_w` wide beside a panel of `panel_width`.
int window_width_for(int frame_w, int panel_width);

}  // namespace penumbra::sandbox
