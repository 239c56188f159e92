// The window layout: the viewport is beside the panel, never under it, at any window size and
// any dragged panel width; the panel width is clamped so both stay usable.
#include <gtest/gtest.h>

#include "sandbox/layout.h"

namespace penumbra::sandbox {
namespace {

TEST(Layout, ViewportIsBesideThePanelNeverUnderIt) {
  for (int window_w : {200, 480, 800, 1280, 2560})
    for (int panel : {0, 100, kDefaultPanelWidth, 900, 5000}) {
      const Layout l = compute_layout(window_w, 720, panel);
      EXPECT_EQ(l.panel.x, 0);
      EXPECT_GE(l.viewport.x, l.panel.x + l.panel.w) << window_w << " " << panel;
      EXPECT_EQ(l.viewport.x + l.viewport.w, window_w) << "the viewport reaches the right edge";
      EXPECT_EQ(l.viewport.h, 720);
      EXPECT_GE(l.viewport.w, std::min(kMinViewportWidth, window_w - kDividerWidth));
      EXPECT_EQ(l.divider.x, l.panel.w);
    }
}

TEST(Layout, PanelWidthFollowsTheDividerWithinLimits) {
  EXPECT_EQ(compute_layout(1280, 800, 500).panel_width, 500);
  EXPECT_EQ(compute_layout(1280, 800, 10).panel_width, kMinPanelWidth);
  EXPECT_EQ(compute_layout(1280, 800, 1270).panel_width, 1280 - kDividerWidth - kMinViewportWidth);
  // A frame of W pixels fits beside the panel in a window of window_width_for(W).
  const Layout l = compute_layout(window_width_for(480, kDefaultPanelWidth), 320, kDefaultPanelWidth);
  EXPECT_EQ(l.viewport.w, 480);
  EXPECT_TRUE(l.viewport.contains(l.viewport.x, 0));
  EXPECT_FALSE(l.panel.contains(l.viewport.x, 0));
}

}  // namespace
}  // namespace penumbra::sandbox
