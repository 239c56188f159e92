#pragma once
// GL-free mapping from a technique's ONE parameter description (graph::ParamDesc) to the widget
// the sandbox draws for it, and the change classification the UI reports. The ImGui code only
// switches on WidgetSpec::kind; unit tests check the mapping without a window.
//
//   WidgetSpec w = widget_for(desc);   // float in [0, 10] -> slider_float, tooltip with unit
#include <string>
#include <vector>

#include "graph/parameters.h"

namespace penumbra::sandbox {

enum class WidgetKind { checkbox, slider_int, drag_int, slider_float, drag_float, combo };

struct WidgetSpec {
  WidgetKind kind = WidgetKind::drag_float;
  std::string label;    // the parameter name
  double min = 0.0;     // slider bounds (sliders only)
  double max = 0.0;
  double drag_speed = 0.0;  // drag widgets only: value change per pixel of mouse motion
  std::vector<std::string> options;  // combo only
  std::string tooltip;  // description, then "[unit]", then "(rebuilds the graph)" if structural
  bool structural = false;
};

const char* widget_kind_name(WidgetKind kind);
WidgetSpec widget_for(const graph::ParamDesc& desc);

// Structural parameters change the graph's shape and recompile it; uniform ones only change the
// value the plan reads every frame (TechniqueSession::compile_count() stays the same).
enum class ChangeKind { structural, uniform };
ChangeKind classify_change(const graph::ParamDesc& desc);
const char* change_kind_name(ChangeKind kind);

}  // namespace penumbra::sandbox
