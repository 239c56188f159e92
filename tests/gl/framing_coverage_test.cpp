// What the default camera shows: on every built-in scene, receivers (shadow-receiving surfaces:
// the model and its ground) cover at least 40% of a 384x256 frame, so a penumbra metric has
// pixels to count (docs/evaluation.md "Pixel classes": the shares of the test assets' glTF models,
// framed by fit_camera, are measured there: 50-81%).
#include <gtest/gtest.h>

#include <algorithm>

#include "scene/builtin_scenes.h"
#include "techniques/builtin_techniques.h"
#include "test_support/technique_rig.h"

namespace penumbra::test {
namespace {

TEST(Framing, ReceiversCoverMostOfTheFrameOnEveryBuiltInScene) {
  constexpr int kW = 384, kH = 256;
  TechniqueRig rig({.width = kW, .height = kH, .shadow_size = 256, .techniques = register_builtin_techniques});
  for (const std::string& name : scene::builtin_scene_names()) {
    const RenderedFrame f = rig.render_frame(builtin_scene(name), "hard");
    ASSERT_EQ(f.coverage.size(), static_cast<size_t>(kW) * kH) << name;
    const auto receivers = std::count(f.coverage.begin(), f.coverage.end(), uint8_t{1});
    EXPECT_GE(static_cast<double>(receivers), 0.4 * kW * kH) << name;
  }
}

}  // namespace
}  // namespace penumbra::test
