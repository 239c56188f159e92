#include "sandbox/layout.h"

#include <algorithm>

namespace penumbra::sandbox {

Layout compute_layout(int window_w, int window_h, int panel_width) {
  Layout l;
  window_w = std::max(window_w, 1);
  window_h = std::max(window_h, 1);
  const int widest = std::max(window_w - kDividerWidth - kMinViewportWidth, 0);
  l.panel_width = std::min(std::max(panel_width, kMinPanelWidth), widest);
  l.panel = {0, 0, l.panel_width, window_h};
  l.divider = {l.panel_width, 0, std::min(kDividerWidth, window_w - l.panel_width), window_h};
  const int x = l.divider.x + l.divider.w;
  l.viewport = {x, 0, std::max(window_w - x, 1), window_h};
  return l;
}

int window_width_for(int frame_w, int panel_width) {
  return std::max(panel_width, kMinPanelWidth) + kDividerWidth + frame_w;
}

}  // namespace penumbra::sandbox
