#pragma once
// Temporal stability of a shadow mask (`penumbra eval --flicker`): how much the mask changes from
// one frame to the next on the same surface point, after reprojecting the previous frame with
// depth, outside disocclusions. A static shadow seen by a moving camera should not change at all;
// a moving light changes the true shadow too, so eval reports a technique's figure minus the
// reference's on the same frames.
//
//   std::vector<SurfaceFrame> frames = ...;   // mask, world positions, camera of each frame
//   Result<TemporalChange> c = temporal_change(frames);
#include <vector>

#include <glm/glm.hpp>

#include "metrics/mask_image.h"
#include "util/error.h"

namespace penumbra::metrics {

struct SurfaceFrame {
  MaskImage mask;                   // rows top to bottom
  std::vector<glm::vec4> position;  // world position per pixel, w > 0 on receivers (gbuffer_position)
  glm::mat4 view_proj{1.0f};        // the camera that rendered it (OpenGL clip convention)
};

struct TemporalChange {
  double mean_abs_change = 0.0;  // mean |mask_t+1(p) - mask_t(reprojected p)| over compared pixels
  size_t pixels = 0;             // compared pixel pairs, over all consecutive frames
  size_t disoccluded = 0;        // receiver pixels with no matching surface in the previous frame
};

// Each receiver pixel p of frame t+1 is projected into frame t with frame t's camera; the previous
// mask is read bilinearly from the neighbours that hold the same surface (their world position
// within `relative_tolerance` x the view depth of p's position; none: p is disoccluded). Frames
// must share one size.
Result<TemporalChange> temporal_change(const std::vector<SurfaceFrame>& frames, float relative_tolerance = 0.01f);

}  // namespace penumbra::metrics
