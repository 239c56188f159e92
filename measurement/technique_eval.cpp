#include "measurement/technique_eval.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "measurement/eval_capture.h"
#include "measurement/progressive_render.h"
#include "technique/frame_graph.h"

namespace penumbra::measurement {

Result<TechniqueEvaluation> evaluate_technique(technique::TechniqueSession& session, const TechniqueSpec& spec,
                                               const std::vector<std::string>& global_sets,
                                               const ReferenceFrame& reference, int warmup, int frames,
                                               metrics::PixelClasses& classes) {
  if (Status s = select_technique(session, spec, global_sets); !s) return s.error();
  if (classes.classes.empty())
    if (Status s = keep_alive(session, {"gbuffer_depth", "gbuffer_normal"}); !s) return s.error();  // pixel classes
  // A progressive technique (the reference evaluated as a technique) runs to completion first. Its
  // first frame tells whether it is one (it reports progress) and counts as a warm-up frame.
  if (Status s = session.render(); !s) return s.error();
  if (const std::optional<exec::PassProgress>& p = session.progress(); p && !p->complete()) {
    const auto t0 = std::chrono::steady_clock::now();
    if (Status s = render_until_complete(session, 65536); !s) return s.error();
    std::fprintf(stderr, "technique %s (%s) done in %.2f s\n", spec.label.c_str(), p->label.c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  if (Status s = render_timed_frames(session, std::max(0, warmup - 1), frames); !s) return s.error();
  gl::Texture* mask = session.executor().resource(technique::kShadowMask);
  if (!mask) return make_error("technique '" + spec.label + "' wrote no shadow_mask", ErrorKind::internal);
  TechniqueEvaluation out;
  out.mask = read_mask_image(*mask);
  if (Status s = frame_classes(session, reference.mask, reference.coverage, classes); !s) return s.error();
  auto errors = metrics::compare_masks(out.mask, reference.mask, reference.coverage, classes);
  if (!errors) return errors.error();
  out.row = {spec.label, *errors, 0.0};
  // The technique's own passes: everything but the frame's G-buffer prologue and lighting epilogue.
  for (const PassMedian& p : pass_medians(session, frames))
    if (p.name != "gbuffer" && p.name != "lighting") out.row.gpu_ms += p.ms;
  return out;
}

}  // namespace penumbra::measurement
