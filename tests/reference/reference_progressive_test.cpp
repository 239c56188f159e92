// Progressive raster accumulation: it converges towards the ray-traced reference as samples
// come in, and the reset rule restarts it when the light moves.
#include <gtest/gtest.h>

#include "metrics/mask_metrics.h"
#include "reference_session.h"
#include "techniques/reference/reference_progress.h"

using namespace penumbra;

TEST(ReferenceProgressive, ErrorToRaytracedFallsAsSamplesAccumulate) {
  test::ReferenceSession r("ball");
  r.set("method=raytraced");
  r.set("rays=256");
  r.render();
  const metrics::MaskImage truth = r.mask();
  const metrics::CoverageMask coverage = r.coverage();
  r.set("method=raster");
  r.set("samples=256");
  r.set("map_size=1024");
  r.set("maps_per_frame=4");
  std::vector<double> rmse;
  int done = 0;
  for (int target : {4, 16, 64, 256}) {
    while (done < target) {
      r.render();
      done += 4;
    }
    ASSERT_EQ(reference::reference_progress().done, target);
    auto e = metrics::compare_masks(r.mask(), truth, coverage);
    ASSERT_TRUE(e);
    rmse.push_back(e->rmse);
  }
  for (size_t i = 1; i < rmse.size(); ++i)
    EXPECT_LT(rmse[i], rmse[i - 1]) << "RMSE after step " << i << ": " << rmse[i] << " vs " << rmse[i - 1];
  EXPECT_LT(rmse.back(), 0.01);
}

TEST(ReferenceProgressive, MovingTheLightResetsTheCount) {
  test::ReferenceSession r("ball");
  r.set("samples=64");
  r.set("map_size=256");
  r.set("maps_per_frame=8");
  r.render(3);
  reference::ReferenceProgress p = reference::reference_progress();
  EXPECT_EQ(p.done, 24);
  EXPECT_EQ(p.total, 64);
  const std::uint64_t resets = p.resets;
  r.render();  // nothing changed: keeps accumulating
  EXPECT_EQ(reference::reference_progress().done, 32);
  r.session().light().position += glm::vec3(0.3f, 0.0f, 0.0f);
  r.render();
  p = reference::reference_progress();
  EXPECT_EQ(p.done, 8) << "a moved light must restart the accumulation";
  EXPECT_EQ(p.resets, resets + 1);
  r.session().camera().position += glm::vec3(0.0f, 0.1f, 0.0f);
  r.render();
  EXPECT_EQ(reference::reference_progress().done, 8) << "a moved camera must restart the accumulation";
  r.render(20);  // runs to completion and stops there
  EXPECT_EQ(reference::reference_progress().done, 64);
  EXPECT_TRUE(reference::reference_progress().complete());
}

TEST(ReferenceProgressive, RaytracedTracesOnlyWhenInputsChange) {
  test::ReferenceSession r("ball", 64);
  r.set("method=raytraced");
  r.set("rays=16");
  r.render();
  const std::uint64_t resets = reference::reference_progress().resets;
  EXPECT_TRUE(reference::reference_progress().complete());
  r.render(2);
  EXPECT_EQ(reference::reference_progress().resets, resets);
  const metrics::MaskImage before = r.mask();
  // Turn the light (a directional light's position alone does not move its shadows).
  r.session().light().direction = glm::normalize(r.session().light().direction + glm::vec3(0.3f, 0.0f, 0.0f));
  r.render();
  EXPECT_EQ(reference::reference_progress().resets, resets + 1);
  EXPECT_NE(before.pixels, r.mask().pixels);
}
