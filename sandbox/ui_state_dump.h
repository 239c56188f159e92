#pragma once
// The window's state as JSON, rewritten every frame with --state-file: what a test that drives
// the real window with X events (xdotool) asserts on. Written whole (PATH.partial, renamed), so
// a reader never sees half of it.
//
//   {"frame": 120, "window": [w, h], "panel": [x, y, w, h], "viewport": [...],
//    "items": {"technique": [x, y, w, h], "reset:samples": [...], ...}, "combos": [...],
//    "open_popup": "view", "popup": [x, y, w, h] | null, "tooltip": [...] | null,
//    "fields": {"preset name": "...", ...}, "technique": "pcss", "params": {"samples": "16", ...},
//    "capped": {"penumbra_kernel_scale": "capped by ..."}, "presets": {"shipped": [...], "saved": [...]},
//    "graph_open": false, "compare": {...}, "viewer": {...}, "pool_textures": 9, "timing": "...",
//    "keys": {"space": 1}, "inspector": {"pixel": [x, y], "texel": [x, y], "text": "..."} | null,
//    "light_direction": [x, y, z], "camera_forward": [x, y, z], "style": {"popup_alpha": 1, ...}}
#include <string>

#include "sandbox/controller.h"
#include "sandbox/layout.h"
#include "sandbox/ui_panels.h"

namespace penumbra::sandbox {

Status write_ui_state(const std::string& path, SandboxController& c, const UiState& ui, const Layout& layout,
                      std::uint64_t frame, int window_w, int window_h);

}  // namespace penumbra::sandbox
