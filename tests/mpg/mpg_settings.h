#pragma once
// Sizes and helpers shared by the mpg tests, with why.
#include <string>
#include <vector>

#include "scene/builtin_scenes.h"

namespace penumbra::test {

// 224x168 screen, 1024^2 shadow map: small enough for llvmpipe (a default frame, ten blur passes
// included, takes about 0.1 s), large enough that the ball's penumbra spans several pixels.
inline constexpr int kWidth = 224;
inline constexpr int kHeight = 168;
inline constexpr int kShadowSize = 1024;

// The built-in scene with its own directional (sun-like) light: the one `penumbra eval` and
// the ray-traced reference use.
inline scene::Scene make_scene(const std::string& name, const scene::ProceduralParams& p = {}) {
  return *scene::make_builtin_scene(name, p);
}

// The pass-4 alterations (section 3.1), the values of the `alteration` parameter.
inline const std::vector<std::string>& alterations() {
  static const std::vector<std::string> names = {"pcf", "gaussian", "multipass"};
  return names;
}

}  // namespace penumbra::test
