#include "app/compare.h"

#include <algorithm>

#include "plugin/frame_graph.h"

namespace penumbra::sandbox {

namespace {
metrics::MaskImage first_channel(const gl::Texture& t, int channel) {
  metrics::MaskImage m(t.width(), t.height());
  std::vector<float> texels = t.read();
  const int n = t.info().channels;
  for (size_t i = 0; i < m.pixels.size(); ++i) m.pixels[i] = texels[i * n + channel];
  return m;
}
}  // namespace

std::string default_compare_partner(const plugin::TechniqueRegistry& registry, const std::string& primary) {
  std::vector<std::string> names = registry.names();
  if (registry.find("reference")) return "reference";
  auto it = std::find(names.begin(), names.end(), primary);
  if (it == names.end() || names.size() == 1) return primary;
  ++it;
  return it == names.end() ? names.front() : *it;
}

Status configure_partner(plugin::TechniqueSession& secondary, plugin::TechniqueSession& primary,
                         const std::string& technique, int width, int height) {
  if (!secondary.has_scene()) secondary.set_scene(primary.scene());
  if (Status s = secondary.resize(width, height); !s) return s;
  if (Status s = secondary.set_shadow_size(primary.settings().shadow_size); !s) return s;
  secondary.compile_options().no_reuse = primary.compile_options().no_reuse;
  secondary.compile_options().extended_lifetimes = primary.compile_options().extended_lifetimes;
  secondary.executor().options().immediate = primary.executor().options().immediate;
  if (secondary.technique() != technique) return secondary.set_technique(technique);
  return {};
}

void update_compare_stats(CompareState& state, plugin::TechniqueSession& primary,
                          plugin::TechniqueSession& secondary) {
  gl::Texture* a = primary.executor().resource(plugin::kShadowMask);
  gl::Texture* b = secondary.executor().resource(plugin::kShadowMask);
  gl::Texture* pos = primary.executor().resource("gbuffer_position");
  if (!a || !b || !pos) {
    state.stats_error = "shadow_mask or gbuffer_position missing";
    return;
  }
  metrics::MaskImage position_w = first_channel(*pos, 3);
  metrics::CoverageMask coverage(position_w.pixels.size());
  for (size_t i = 0; i < coverage.size(); ++i) coverage[i] = position_w.pixels[i] > 0.0f ? 1 : 0;
  // The secondary plays the reference: RMSE of the primary against it.
  Result<metrics::MaskErrors> e = metrics::compare_masks(first_channel(*a, 0), first_channel(*b, 0), coverage);
  if (!e) {
    state.stats_error = e.error().to_string();
    return;
  }
  state.stats = *e;
  state.stats_error.clear();
  state.rmse_history.push_back(static_cast<float>(e->rmse));
  if (state.rmse_history.size() > CompareState::kHistory) state.rmse_history.erase(state.rmse_history.begin());
}

}  // namespace penumbra::sandbox
