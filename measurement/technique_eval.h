#pragma once
// One technique (with its own settings) on the session's frame, compared with the reference of
// that frame: the row `eval` prints, and the objective `calibrate` minimises.
#include <string>
#include <vector>

#include "measurement/eval_report.h"
#include "measurement/reference_frame.h"
#include "measurement/technique_spec.h"
#include "metrics/mask_image.h"
#include "metrics/pixel_classes.h"
#include "technique/technique_session.h"

namespace penumbra::measurement {

struct TechniqueEvaluation {
  EvalRow row;                // errors against the reference, median ms of the technique's passes
  metrics::MaskImage mask;    // its shadow_mask, rows top to bottom
};

// Selects `spec` (global_sets first, then its own), renders warmup + frames frames (a listed
// `reference` runs to completion first), reads the mask and compares it, split by `classes`: the
// frame's pixel classes, the same for every technique, computed from this frame's G-buffer when
// empty (the first technique of an eval) and reused after.
Result<TechniqueEvaluation> evaluate_technique(technique::TechniqueSession& session, const TechniqueSpec& spec,
                                               const std::vector<std::string>& global_sets,
                                               const ReferenceFrame& reference, int warmup, int frames,
                                               metrics::PixelClasses& classes);

}  // namespace penumbra::measurement
