// esm renders on every light type and writes its debug resources.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "esm_rig.h"
#include "scene/builtin_scenes.h"

using namespace penumbra;

TEST(EsmSmoke, BallDirectionalWritesMaskAndDebugViews) {
  test::EsmRig rig(512, 384, 256);
  rig.set_scene(*scene::make_builtin_scene("ball"));
  rig.use("esm");
  rig.render();
  const metrics::MaskImage mask = rig.shadow_mask();
  const auto [lo, hi] = std::minmax_element(mask.pixels.begin(), mask.pixels.end());
  EXPECT_EQ(*lo, 0.0f);
  EXPECT_EQ(*hi, 1.0f);
  const metrics::MaskImage sil = rig.read("esm_silhouette_mask");
  const metrics::MaskImage dist = rig.read("esm_edge_distance");
  ASSERT_EQ(sil.width, 256);
  EXPECT_GT(*std::max_element(sil.pixels.begin(), sil.pixels.end()), 0.5f);
  test::save_for_inspection("ball_mask", mask);
  test::save_for_inspection("ball_silhouette", sil);
  metrics::MaskImage d01 = dist;
  for (float& v : d01.pixels) v = (v + 1.5f) / 4.5f;
  test::save_for_inspection("ball_distance", d01);
  metrics::MaskImage depth = rig.read("esm_edge_depth");
  test::save_for_inspection("ball_depth", depth);
}

// The nearest-edge channel (esm_common.glsl, edge_near): written exactly where a quad wrote (the
// edge channel's mark), and its edge never lies behind the texel's farthest edge (edge_depth).
// Its integer part holds 65535 - the depth in 1/65534 steps, rounded up; a texel no quad reaches
// holds 0. Showcase: pickets, bars and the ball overlap in the map.
TEST(EsmSmoke, TheNearestEdgeIsWrittenWithEveryQuadAndNeverBehindTheFarthest) {
  test::EsmRig rig(320, 240, 512);
  rig.set_scene(*scene::make_builtin_scene("showcase"));
  rig.use("esm");
  rig.render();
  const metrics::MaskImage edge = rig.read("esm_edge"), far = rig.read("esm_edge_depth"), near = rig.read("esm_edge_near");
  constexpr float kQuadMark = 2.0f, kSteps = 65535.0f;
  size_t quads = 0, nearer = 0;
  for (size_t i = 0; i < edge.pixels.size(); ++i) {
    const bool quad = edge.pixels[i] >= kQuadMark;
    ASSERT_EQ(near.pixels[i] >= 1.0f, quad) << "texel " << i;
    if (!quad) continue;
    ++quads;
    const float near_depth = (kSteps - std::floor(near.pixels[i])) / (kSteps - 1.0f);
    EXPECT_LE(near_depth, far.pixels[i] + 1.0f / (kSteps - 1.0f)) << "texel " << i;
    nearer += near_depth < far.pixels[i] - 1e-3f ? 1 : 0;
  }
  EXPECT_GT(quads, 1000u);
  EXPECT_GT(nearer, 0u) << "no texel where two edges at different depths meet";
}
