#pragma once
// The ground truth of one frame (scene, camera, light, size) for `eval` and `calibrate`: the
// reference technique rendered to completion and read back, with the receiver coverage. A
// ray-traced reference at 1080p costs seconds to minutes, so finished references are cached on
// disk, keyed by everything that decides them (scene file and its modification time or the
// built-in's name, camera, light, screen size, every reference parameter, the cache format).
//
//   ReferenceSettings settings{.method = "raytraced", .rays = 256};
//   Result<ReferenceFrame> ref = reference_frame(session, settings);   // session has the scene
//   if (ref && ref->from_cache) ...
//
// Cache folder: $PENUMBRA_CACHE_DIR, else $XDG_CACHE_HOME/penumbra, else ~/.cache/penumbra;
// PENUMBRA_CACHE_DIR=off turns the cache off (the test suites do: a test must see its own
// reference); `--no-cache` (use_cache = false) renders and does not write.
#include <string>
#include <vector>

#include "metrics/mask_image.h"
#include "technique/technique_session.h"
#include "util/error.h"

namespace penumbra::measurement {

// The technique every measurement compares with: the ground truth.
inline constexpr const char* kReferenceTechnique = "reference";

struct ReferenceSettings {
  std::string method = "raytraced";  // or "raster"
  int rays = 256;                    // raytraced: rays per pixel
  int samples = 1024;                // raster: light sample points
  std::vector<std::string> sets;     // --set k=v the reference has (pixel_samples, seed, ...)
  bool use_cache = true;
};

struct ReferenceFrame {
  metrics::MaskImage mask;          // rows top to bottom
  metrics::CoverageMask coverage;   // receiver pixels
  bool from_cache = false;
  std::string cache_file;           // where it was read from or written to ("" when not cached)
};

// Renders (or reads) the reference of the session's current scene, camera, light and size. The
// session's technique is left set to kReferenceTechnique.
Result<ReferenceFrame> reference_frame(technique::TechniqueSession& session, const ReferenceSettings& settings);

}  // namespace penumbra::measurement
