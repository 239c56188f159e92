#pragma once
// The baseline tests' renderer: the generic technique rig (test_support/technique_rig.h) over
// the built-in techniques, each frame set up in one call (scene, technique, parameters, sizes).
#include <map>
#include <string>

#include "test_support/technique_rig.h"

namespace penumbra::test {

class BaselineRenderer : public TechniqueRig {
 public:
  BaselineRenderer();
  // Renders `frames` frames (timings are medians over them) of `technique` on `scene` with
  // `params` ("k" -> "v") at width x height, shadow map `shadow_size` texels, read back.
  RenderedFrame render(const scene::Scene& scene, const std::string& technique,
                       const std::map<std::string, std::string>& params, int width, int height,
                       int frames = 1, int shadow_size = 2048);
};

}  // namespace penumbra::test
