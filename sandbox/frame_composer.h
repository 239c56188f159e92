#pragma once
// Composing the presentation image of a frame: the primary's colour, or compare mode's split
// (left primary, right secondary) or |a - b| heat map, then the resource viewer's layer (full
// or an inset with the texture's aspect). And writing that image as PNG.
//
//   compose_frame(display, {primary, secondary_or_null, compare, viewer, w, h});
#include <string>

#include "sandbox/compare.h"
#include "sandbox/display.h"
#include "technique/technique_session.h"

namespace penumbra::sandbox {

struct FrameInputs {
  technique::TechniqueSession& primary;
  technique::TechniqueSession* secondary;  // null when not comparing
  technique::TechniqueSession* third;      // three-way compare's reference; null otherwise
  const CompareState& compare;
  const ViewerSettings& viewer;
  int width = 0, height = 0;  // the frame, pixels
  bool texel_density = false;  // replace the base image by the shadow-map texel density view
};

Status compose_frame(DisplayPass& display, const FrameInputs& in);

// The presentation target, first row at the top.
Status save_target_png(const DisplayPass& display, const std::string& path);

}  // namespace penumbra::sandbox
