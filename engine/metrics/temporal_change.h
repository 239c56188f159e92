#pragma once
// Temporal stability of a shadow mask (`penumbra eval --flicker`): how much the mask changes from
// one frame to the next on the same surface point, after reprojecting the previous frame with
// depth, outside disocclusions. A static shadow seen by a moving camera should not change at all;
// a moving light changes the true shadow too, so eval reports a technique's figure minus the
// reference's on the same frames, and its temporal error: the change per pixel that the
// reference's does not share.
//
//   std::vector<SurfaceFrame> frames = ...;   // mask, world positions, camera of each frame
//   Result<TemporalChange> c = temporal_change(frames);
//   Result<TemporalChange> e = temporal_error(frames, reference_frames);
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
                                 // (temporal_error: of that change minus the truth's, per pixel)
  size_t pixels = 0;             // compared pixel pairs, over all consecutive frames
  size_t disoccluded = 0;        // receiver pixels with no matching surface in the previous frame
  size_t unmatched = 0;          // match_within > 0: receiver pixels left out for landing off a centre
};

// How the previous frame is read at a pixel's reprojection.
struct Reprojection {
  float relative_tolerance = 0.01f;  // a neighbour holds the same surface within this x view depth
  // 0: bilinear from the neighbours that hold the surface. > 0 (pixels): only pixels whose
  // reprojection lands within this of a pixel centre on both axes, read from that pixel alone:
  // bilinear resampling changes a sharp mask more than a blurred one (up to 0.5 at an edge
  // pixel), which this removes, at the price of comparing fewer pixels.
  float match_within = 0.0f;
};

// Each receiver pixel p of frame t+1 is projected into frame t with frame t's camera; the previous
// mask is read as `how` says from the neighbours that hold the same surface (none: p is
// disoccluded). Frames must share one size.
Result<TemporalChange> temporal_change(const std::vector<SurfaceFrame>& frames, const Reprojection& how = {});

// Mean over pixels of |change of `frames` - change of `truth`|, each sequence reprojected as
// above, over the pixels both compare (the others count as disoccluded). Unlike the difference of
// two temporal_change figures, it is zero only for a sequence that changes as the truth does:
// a blurred mask changes less than a sharp truth under a pan (its resampling error is smaller)
// and would score below a perfect one by that difference. Both sequences must share the frames'
// count and size, and the same cameras.
Result<TemporalChange> temporal_error(const std::vector<SurfaceFrame>& frames, const std::vector<SurfaceFrame>& truth,
                                      const Reprojection& how = {});

}  // namespace penumbra::metrics
