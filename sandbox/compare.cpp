#include "sandbox/compare.h"

#include <algorithm>
#include <cmath>

#include "measurement/eval_capture.h"
#include "measurement/reference_frame.h"
#include "technique/frame_graph.h"

namespace penumbra::sandbox {

std::string default_compare_partner(const technique::TechniqueRegistry& registry, const std::string& primary) {
  std::vector<std::string> names = registry.names();
  if (registry.find(measurement::kReferenceTechnique)) return measurement::kReferenceTechnique;
  auto it = std::find(names.begin(), names.end(), primary);
  if (it == names.end() || names.size() == 1) return primary;
  ++it;
  return it == names.end() ? names.front() : *it;
}

Status configure_partner(technique::TechniqueSession& secondary, technique::TechniqueSession& primary,
                         const std::string& technique, int width, int height) {
  if (!secondary.has_scene()) secondary.set_scene(primary.scene());
  if (Status s = secondary.resize(width, height); !s) return s;
  if (Status s = secondary.set_shadow_size(primary.settings().shadow_size); !s) return s;
  if (Status s = secondary.set_cascades(primary.cascades()); !s) return s;
  secondary.compile_options().no_reuse = primary.compile_options().no_reuse;
  secondary.compile_options().extended_lifetimes = primary.compile_options().extended_lifetimes;
  secondary.executor().options().immediate = primary.executor().options().immediate;
  if (secondary.technique() != technique) return secondary.set_technique(technique);
  return {};
}

namespace {

// The errors of `test` against `reference`, split by the pixel classes of test's G-buffer and the
// reference's mask (also returned in `classes`).
Result<metrics::MaskErrors> mask_errors(technique::TechniqueSession& test, technique::TechniqueSession& reference,
                                        metrics::PixelClasses& classes) {
  gl::Texture* a = test.executor().resource(technique::kShadowMask);
  gl::Texture* b = reference.executor().resource(technique::kShadowMask);
  gl::Texture* depth = test.executor().resource("gbuffer_depth");
  if (!a || !b || !depth) return make_error("shadow_mask or gbuffer_depth missing");
  Result<metrics::ReceiverGeometry> geometry = measurement::read_receiver_geometry(test);
  if (!geometry) return geometry.error();
  const metrics::MaskImage ref = measurement::read_mask_image(*b);
  const metrics::CoverageMask coverage = measurement::read_coverage(*depth);
  classes = metrics::classify_pixels(ref, coverage, &*geometry);
  return metrics::compare_masks(measurement::read_mask_image(*a), ref, coverage, classes);
}

}  // namespace

void update_compare_stats(CompareState& state, technique::TechniqueSession& primary,
                          technique::TechniqueSession& secondary, technique::TechniqueSession* reference) {
  // The secondary plays the reference, unless a third session runs it.
  Result<metrics::MaskErrors> e = mask_errors(primary, reference ? *reference : secondary, state.classes);
  ++state.classes_version;
  if (!e) {
    state.stats_error = e.error().to_string();
    return;
  }
  state.stats = *e;
  state.stats_b.reset();
  if (reference) {
    metrics::PixelClasses classes_b;  // the same frame: the same classes
    Result<metrics::MaskErrors> b = mask_errors(secondary, *reference, classes_b);
    if (!b) {
      state.stats_error = "B: " + b.error().to_string();
      return;
    }
    state.stats_b = *b;
  }
  state.stats_error.clear();
  state.rmse_history.push_back(static_cast<float>(e->rmse));
  if (state.rmse_history.size() > CompareState::kHistory) state.rmse_history.erase(state.rmse_history.begin());
}

std::vector<int> column_edges(const CompareState& state, int width, int columns) {
  auto px = [&](float f) { return std::clamp(static_cast<int>(std::lround(f * float(width))), 0, width); };
  std::vector<int> edges = {0, px(state.split)};
  if (columns == 3) edges.push_back(std::max(px(state.split2), edges[1]));
  edges.push_back(width);
  return edges;
}

}  // namespace penumbra::sandbox
