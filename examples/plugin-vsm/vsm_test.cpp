// The VSM plugin's tests, written with Penumbra::test_support (docs/testing.md shows this file).
// They load the built plugin directory, as `penumbra --plugin-dir` does, and assert properties:
// lit stays exactly 1, the ball casts an umbra, the penumbra widens with the blur radius, and
// the mask pass alone (fed known moments by an upload pass) gives 0 behind a near occluder and
// 1 in front of a far one.
#include <gtest/gtest.h>

#include <algorithm>

#include "gl/shader_files.h"
#include "test_support/technique_rig.h"
#include "test_support/upload_pass.h"

namespace {

using penumbra::graph::Format;
using namespace penumbra::test;

// Pixels of the mask on receivers (coverage 1) strictly between lo and hi.
int count_between(const penumbra::metrics::MaskImage& mask, const penumbra::metrics::CoverageMask& coverage,
                  float lo, float hi) {
  int n = 0;
  for (size_t i = 0; i < mask.pixels.size(); ++i) n += coverage[i] && mask.pixels[i] > lo && mask.pixels[i] < hi;
  return n;
}

TEST(Vsm, LitStaysOneTheBallCastsAnUmbraAndBlurWidensThePenumbra) {
  TechniqueRig rig({.width = 96, .height = 72, .shadow_size = 512, .technique = "vsm",
                    .plugin_dirs = {VSM_PLUGIN_DIR}});
  rig.set_scene(builtin_scene("ball"));
  rig.set({"blur_radius=0"});
  rig.render();
  const penumbra::metrics::MaskImage sharp = rig.shadow_mask();
  const penumbra::metrics::CoverageMask coverage = rig.coverage();
  ASSERT_EQ(sharp.pixels.size(), 96u * 72u);
  for (size_t i = 0; i < sharp.pixels.size(); ++i)
    if (!coverage[i]) ASSERT_EQ(sharp.pixels[i], 1.0f) << "background is lit";
  EXPECT_GT(count_between(sharp, coverage, -1.0f, 0.05f), 20) << "the ball's umbra";
  EXPECT_GT(count_between(sharp, coverage, 0.999f, 2.0f), 96 * 72 / 4) << "lit ground stays exactly 1";

  rig.set({"blur_radius=8"});
  rig.render();
  const penumbra::metrics::MaskImage soft = rig.shadow_mask();
  EXPECT_GT(count_between(soft, coverage, 0.05f, 0.95f), count_between(sharp, coverage, 0.05f, 0.95f))
      << "a wider box filter, a wider penumbra";
}

// The mask pass on its own: an upload pass writes the moments (mean, mean of squares of the
// light distance, world units) of every shadow-map texel, and the rig renders a technique made
// of that and vsm_mask.
penumbra::metrics::MaskImage mask_over_moments(float mean) {
  const int shadow = 64;
  TextureImage moments{shadow, shadow, 2, {}};
  for (int i = 0; i < shadow * shadow; ++i) moments.texels.insert(moments.texels.end(), {mean, mean * mean});
  TechniqueRig rig({.width = 64, .height = 48, .shadow_size = shadow, .technique = "vsm_known_moments",
                    .techniques = [&](penumbra::technique::TechniqueRegistry& registry) {
                      penumbra::gl::ShaderFileSystem::default_instance().add_root(VSM_TEST_DIR);
                      registry.add({.name = "vsm_known_moments",
                                    .graph_file = "known_moments.json",
                                    .register_passes = [moments](penumbra::exec::PassLibrary& library) {
                                      library.add(upload_pass_type("upload_moments", Format::RG32F, moments));
                                    }});
                    },
                    .plugin_dirs = {VSM_PLUGIN_DIR}});  // vsm_mask
  rig.set_scene(builtin_scene("ball"));
  rig.render();
  return rig.shadow_mask();
}

TEST(VsmMask, BehindANearOccluderIsDarkInFrontOfAFarOneLit) {
  const penumbra::metrics::MaskImage far = mask_over_moments(1e4f);
  ASSERT_FALSE(far.pixels.empty());
  EXPECT_EQ(*std::min_element(far.pixels.begin(), far.pixels.end()), 1.0f) << "every receiver is in front";

  const penumbra::metrics::MaskImage near = mask_over_moments(0.0f);
  ASSERT_EQ(near.pixels.size(), far.pixels.size());
  const auto dark = std::count_if(near.pixels.begin(), near.pixels.end(), [](float v) { return v < 0.01f; });
  EXPECT_GT(dark, static_cast<long>(near.pixels.size()) / 4) << "receivers inside the map are behind the occluder";
  for (float v : near.pixels) EXPECT_TRUE(v < 0.01f || v == 1.0f) << "dark inside the map, 1 outside: " << v;
}

}  // namespace
