#include "sandbox/widget_spec.h"

#include <algorithm>
#include <cmath>

namespace penumbra::sandbox {

const char* widget_kind_name(WidgetKind kind) {
  switch (kind) {
    case WidgetKind::checkbox: return "checkbox";
    case WidgetKind::slider_int: return "slider_int";
    case WidgetKind::drag_int: return "drag_int";
    case WidgetKind::slider_float: return "slider_float";
    case WidgetKind::drag_float: return "drag_float";
    case WidgetKind::combo: return "combo";
  }
  return "?";
}

WidgetSpec widget_for(const graph::ParamDesc& desc) {
  WidgetSpec w;
  w.label = desc.name;
  w.structural = desc.structural;
  w.tooltip = desc.description;
  if (!desc.unit.empty()) w.tooltip += (w.tooltip.empty() ? "[" : " [") + desc.unit + "]";
  if (desc.structural) w.tooltip += (w.tooltip.empty() ? "" : " ") + std::string("(rebuilds the graph)");
  switch (desc.type) {
    case graph::ParamType::boolean:
      w.kind = WidgetKind::checkbox;
      break;
    case graph::ParamType::enumeration:
      w.kind = WidgetKind::combo;
      w.options = desc.options;
      break;
    case graph::ParamType::integer:
      w.kind = desc.has_range() ? WidgetKind::slider_int : WidgetKind::drag_int;
      w.drag_speed = desc.has_range() ? 0.0 : 0.2;
      break;
    case graph::ParamType::real: {
      w.kind = desc.has_range() ? WidgetKind::slider_float : WidgetKind::drag_float;
      if (!desc.has_range()) {
        // Unbounded: about 1% of the default's magnitude per pixel, so a drag across the panel
        // roughly doubles it; 0.01 for a zero default.
        const double* d = std::get_if<double>(&desc.default_value);
        double mag = d ? std::abs(*d) : 0.0;
        w.drag_speed = std::max(0.01 * mag, 0.01);
      }
      break;
    }
  }
  if (desc.has_range()) {
    w.min = desc.min;
    w.max = desc.max;
  }
  return w;
}

ChangeKind classify_change(const graph::ParamDesc& desc) {
  return desc.structural ? ChangeKind::structural : ChangeKind::uniform;
}

const char* change_kind_name(ChangeKind kind) {
  return kind == ChangeKind::structural ? "structural (recompiles)" : "uniform (value only)";
}

}  // namespace penumbra::sandbox
