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
#include "scene/camera.h"
#include "technique/technique_session.h"

namespace penumbra::measurement {

struct FlickerSettings {
  std::string motion = "pan";      // "pan" or "light"
  int frames = 8;
  float degrees_per_frame = 0.25f;
  // Pan only, > 0: the step is the turn that moves the image centre by this many pixels
  // (resolved_flicker sets degrees_per_frame from the camera). With whole pixels a wide band
  // around the centre lands on pixel centres, which --flicker-match compares; an arbitrary
  // angle leaves a few thin bands, or none.
  float pixels_per_frame = 0.0f;
  metrics::Reprojection reprojection;  // how a frame is compared with the previous one
};

Status check_flicker_motion(const std::string& motion);

// The turn about the vertical (degrees) that moves the image centre of `camera`'s view, `width` x
// `height` pixels, by `pixels`: a turn about the world's vertical keeps the pitch, so every step
// of the pan moves it as far. An error where even half the vertical field of view is too little.
Result<float> pan_degrees_for_pixels(const scene::Camera& camera, int width, int height, float pixels);

// `flicker` with a step given in pixels turned into degrees for the session's camera and screen
// (unchanged otherwise).
Result<FlickerSettings> resolved_flicker(technique::TechniqueSession& session, const FlickerSettings& flicker);

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
