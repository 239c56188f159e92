#include "cli/technique_eval.h"

#include <chrono>
#include <cstdio>

#include "cli/eval_capture.h"
#include "plugin/frame_graph.h"
#include "techniques/reference/reference_progress.h"

namespace penumbra::cli {

Result<TechniqueEvaluation> evaluate_technique(plugin::TechniqueSession& session, const TechniqueSpec& spec,
                                               const std::vector<std::string>& global_sets,
                                               const ReferenceFrame& reference, int warmup, int frames) {
  if (Status s = select_technique(session, spec, global_sets); !s) return s.error();
  if (spec.name == "reference") {  // a reference evaluated as a technique runs to completion first
    const auto t0 = std::chrono::steady_clock::now();
    for (int f = 0; f < 1 + 65536; ++f) {
      if (Status s = session.render(); !s) return s.error();
      if (reference::reference_progress().complete()) break;
    }
    std::fprintf(stderr, "technique reference (%s) done in %.2f s\n", session.params().get_enum("method").c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  if (Status s = render_timed_frames(session, warmup, frames); !s) return s.error();
  gl::Texture* mask = session.executor().resource(plugin::kShadowMask);
  if (!mask) return make_error("technique '" + spec.label + "' wrote no shadow_mask", ErrorKind::internal);
  TechniqueEvaluation out;
  out.mask = read_mask_image(*mask);
  auto errors = metrics::compare_masks(out.mask, reference.mask, reference.coverage);
  if (!errors) return errors.error();
  out.row = {spec.label, *errors, 0.0};
  // The technique's own passes: everything but the frame's G-buffer prologue and lighting epilogue.
  for (const PassMedian& p : pass_medians(session, frames))
    if (p.name != "gbuffer" && p.name != "lighting") out.row.gpu_ms += p.ms;
  return out;
}

}  // namespace penumbra::cli
