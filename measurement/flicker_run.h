#pragma once
// `penumbra eval --flicker pan|light`: a slow motion of a few frames, rendered once with the
// reference and once per technique, and each sequence's temporal change
// (metrics/temporal_change.h). A technique's flicker is its change minus the reference's: what it
// adds to the change the motion itself causes (none for a pan, the shadow's true motion for a
// moving light). Sterna's low-resolution penumbra mask "swims" under a pan; this measures it.
//
//   pan    the camera turns by `degrees_per_frame` about the vertical axis, each frame
//   light  the light turns by `degrees_per_frame` about the vertical axis through the scene centre
#include <string>
#include <vector>

#include "measurement/reference_frame.h"
#include "measurement/technique_spec.h"
#include "metrics/temporal_change.h"
#include "technique/technique_session.h"

namespace penumbra::measurement {

struct FlickerSettings {
  std::string motion = "pan";      // "pan" or "light"
  int frames = 8;
  float degrees_per_frame = 0.25f;
  metrics::Reprojection reprojection;  // how a frame is compared with the previous one
};

Status check_flicker_motion(const std::string& motion);

// The reference's frames of the motion (masks and positions; the session's camera and light are
// restored afterwards).
Result<std::vector<metrics::SurfaceFrame>> reference_motion_frames(technique::TechniqueSession& session,
                                                                   const ReferenceSettings& reference,
                                                                   const FlickerSettings& flicker);
// The technique's frames of the same motion.
Result<std::vector<metrics::SurfaceFrame>> technique_motion_frames(technique::TechniqueSession& session,
                                                                   const TechniqueSpec& spec,
                                                                   const std::vector<std::string>& global_sets,
                                                                   const FlickerSettings& flicker);

}  // namespace penumbra::measurement
