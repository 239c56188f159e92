#pragma once
// What `penumbra eval` and `penumbra bench` read back from a TechniqueSession: masks and
// coverage as metrics images (rows top to bottom), per-pass median times, and the --set
// assignments that apply to a technique.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "metrics/mask_image.h"
#include "metrics/pixel_classes.h"
#include "technique/technique_session.h"
#include "util/error.h"

namespace penumbra::measurement {

// A single-channel view of channel 0 of `texture`, flipped to rows top to bottom.
metrics::MaskImage read_mask_image(const gl::Texture& texture);
// Receiver pixels: gbuffer_depth > 0 (the frame contract), rows top to bottom.
metrics::CoverageMask read_coverage(const gl::Texture& gbuffer_depth);
// Adds `resources` to what the session's plan keeps alive for read-back after a frame (and
// recompiles) when they are not kept yet.
Status keep_alive(technique::TechniqueSession& session, const std::vector<std::string>& resources);
// The last frame's receivers for the pixel classes (metrics/pixel_classes.h): view depth, world
// normal and N · (direction to the session's light), rows top to bottom. Needs gbuffer_depth and
// gbuffer_normal kept alive (keep_alive above).
Result<metrics::ReceiverGeometry> read_receiver_geometry(technique::TechniqueSession& session);
// Fills `classes`, when empty, with the pixel classes of the last frame against its reference
// (classify_pixels with the frame's receiver geometry): what every penumbra RMSE of the
// measurements is taken over. The G-buffer is the same for every technique of a frame, so callers
// keep `classes` and this classifies once.
Status frame_classes(technique::TechniqueSession& session, const metrics::MaskImage& reference,
                     const metrics::CoverageMask& coverage, metrics::PixelClasses& classes);
// Renders `warmup` frames, then `frames` measured frames (plus the timer's read-back latency
// when timings come from GPU timestamp queries, so the measured frames are the last ones read).
Status render_timed_frames(technique::TechniqueSession& session, int warmup, int frames);

struct PassMedian {
  std::string name;
  double ms = 0.0;
};
// Median over the last `frames` measurements of each pass of the session's plan.
std::vector<PassMedian> pass_medians(technique::TechniqueSession& session, int frames);

// "gpu timestamps" / "glFinish + CPU clock (software renderer: timer queries do not measure
// llvmpipe's work)" / "off".
std::string timing_mode_note(technique::TechniqueSession& session);

// Every --set k=v must name a parameter of at least one of `techniques` (their graphs are read,
// no GL needed); returns an Error naming the key and the techniques otherwise.
Status check_set_keys(const technique::TechniqueRegistry& registry, const std::vector<std::string>& techniques,
                      const std::vector<std::string>& assignments);
// Applies the assignments whose key the session's current technique has.
Status apply_matching_sets(technique::TechniqueSession& session, const std::vector<std::string>& assignments);

// "a,b,c" -> {"a","b","c"}; empty items are an error naming the option.
Result<std::vector<std::string>> split_list(const std::string& option, const std::string& text);

}  // namespace penumbra::measurement
