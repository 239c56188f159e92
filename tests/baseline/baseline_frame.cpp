#include "baseline_frame.h"

#include "techniques/builtin_techniques.h"

namespace penumbra::test {

BaselineRenderer::BaselineRenderer() : TechniqueRig({.techniques = register_builtin_techniques}) {}

RenderedFrame BaselineRenderer::render(const scene::Scene& scene, const std::string& technique,
                                       const std::map<std::string, std::string>& params, int width,
                                       int height, int frames, int shadow_size) {
  resize(width, height);
  set_shadow_size(shadow_size);
  std::vector<std::string> settings;
  for (const auto& [k, v] : params) settings.push_back(k + "=" + v);
  return render_frame(scene, technique, settings, frames);
}

}  // namespace penumbra::test
