// esm renders on every light type and writes its debug resources.
#include <gtest/gtest.h>

#include <algorithm>

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
