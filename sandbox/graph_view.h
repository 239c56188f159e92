#pragma once
// The graph view panel: the compiled plan laid out by dot (graph_layout.h) and drawn with
// ImGui — passes as nodes (the slowest highlighted, culled and disabled ones greyed with why;
// click a pass to view its first output), resources as edges — then each pass's time against a
// frame-budget line, and the physical textures' lifetimes as a timeline (shared textures show as
// several versions on one row).
#include <string>

#include "sandbox/controller.h"
#include "sandbox/ui_widgets.h"
#include "sandbox/graph_export.h"
#include "sandbox/graph_layout.h"
#include "sandbox/graph_view_model.h"

namespace penumbra::sandbox {

struct GraphViewCache {
  std::string key;  // plan identity: technique, compile count, pass names
  GraphViewModel model;
  GraphLayout layout;
  std::string error;
  float budget_ms = 16.667f;
};

void draw_graph_view(SandboxController& c, GraphViewCache& cache, UiProbe& probe);

}  // namespace penumbra::sandbox
