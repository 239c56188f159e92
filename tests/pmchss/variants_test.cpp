// The variants agree where the paper says they should: blur only touches penumbrae,
// checkerboard ~ full resolution on planar receivers, penumbra mask ~ regular CHSS.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "metrics/mask_metrics.h"
#include "pmchss_fixture.h"
#include "pmchss_settings.h"

using namespace penumbra;

namespace {

std::unique_ptr<test::PmchssRig> ball_rig() {
  auto rig = std::make_unique<test::PmchssRig>(test::kWidth, test::kHeight, test::kShadowSize);
  rig->set_scene(test::make_scene("ball", {{"ball_height", 0.5f}}));
  rig->set(test::test_settings());
  rig->set({"k=" + std::to_string(test::kCalibratedK)});
  return rig;
}

metrics::MaskImage render(test::PmchssRig& rig, const std::vector<std::string>& settings) {
  rig.set(settings);
  rig.render();
  return rig.shadow_mask();
}

// Ground pixels whose 3x3 neighbourhood is all ground: a plane, no depth edge nearby.
std::vector<bool> planar_ground(const metrics::MaskImage& y) {
  std::vector<bool> planar(y.pixels.size(), false);
  for (int j = 1; j + 1 < y.height; ++j)
    for (int i = 1; i + 1 < y.width; ++i) {
      bool ok = true;
      for (int dj = -1; dj <= 1 && ok; ++dj)
        for (int di = -1; di <= 1 && ok; ++di) {
          float v = y.at(i + di, j + dj);
          ok = !std::isnan(v) && std::abs(v) < 0.01f;
        }
      planar[static_cast<size_t>(j) * y.width + i] = ok;
    }
  return planar;
}

}  // namespace

// Section 2.2: the blur only smooths the penumbra mask, i.e. the kernel size. A pixel fully lit
// with one kernel can be partly shadowed with another, but never fully shadowed: no pixel may
// be <= 0.02 in one image and >= 0.98 in the other (umbra and full light stay where they are),
// and the blur must change something (mean |difference| over penumbra pixels > 0.005).
TEST(PmchssVariants, MaskBlurChangesOnlyPenumbraPixels) {
  auto rig = ball_rig();
  metrics::MaskImage on = render(*rig, {"variant=penumbra_mask", "mask_blur=true"});
  metrics::MaskImage off = render(*rig, {"mask_blur=false"});
  size_t flips = 0, penumbra = 0;
  double change = 0.0;
  for (size_t i = 0; i < on.pixels.size(); ++i) {
    float a = on.pixels[i], b = off.pixels[i];
    if ((a <= 0.02f && b >= 0.98f) || (a >= 0.98f && b <= 0.02f)) ++flips;
    bool both_full = (a == 1.0f && b == 1.0f) || (a == 0.0f && b == 0.0f);
    if (!both_full) {
      ++penumbra;
      change += std::abs(a - b);
    }
  }
  std::printf("[ measure  ] blur on/off: %zu penumbra pixels, mean |diff| %.4f, %zu flips\n", penumbra,
              change / std::max<size_t>(penumbra, 1), flips);
  EXPECT_EQ(flips, 0u);
  ASSERT_GT(penumbra, 50u);
  EXPECT_GT(change / penumbra, 0.005);
}

// Section 3: on planar receivers the checkerboard result matches full resolution. Computed
// pixels differ only through the noise (y x 4, Listing 7); filled pixels are a depth-weighted
// average of four computed neighbours. Measured on the ball's ground shadow: RMSE 0.03x over
// planar ground pixels for both variants; tolerance 0.05 (noise of 16 taps is ~0.1 per pixel
// in a wide penumbra, averaging four neighbours halves it).
TEST(PmchssVariants, CheckerboardMatchesFullResolutionOnPlanes) {
  auto rig = ball_rig();
  for (const char* variant : {"regular", "penumbra_mask"}) {
    metrics::MaskImage full = render(*rig, {std::string("variant=") + variant, "checkerboard=false"});
    metrics::MaskImage checker = render(*rig, {"checkerboard=true"});
    std::vector<bool> planar = planar_ground(rig->world_y());
    double sq = 0.0, worst = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < full.pixels.size(); ++i) {
      if (!planar[i]) continue;
      double d = std::abs(full.pixels[i] - checker.pixels[i]);
      sq += d * d;
      worst = std::max(worst, d);
      ++n;
    }
    double rmse = std::sqrt(sq / std::max<size_t>(n, 1));
    std::printf("[ measure  ] %s checkerboard vs full on %zu planar pixels: RMSE %.4f, max %.3f\n", variant,
                n, rmse, worst);
    test::save_for_inspection(std::string("checker_") + variant, checker);
    ASSERT_GT(n, 1000u);
    EXPECT_LT(rmse, 0.05) << variant;
  }
}

// checker_depth_epsilon reaches the upsample pass (its eps, Sterna 2018 section 3): at 1e-6 a
// filled pixel averages only neighbours on its own surface, at 10 all four alike, so pixels
// next to depth edges (the ball's outline over the ground) differ. Before the technique exposed
// the pass's parameter, nothing bound it and both renders were byte-identical.
TEST(PmchssVariants, CheckerDepthEpsilonChangesTheFilledPixels) {
  auto rig = ball_rig();
  metrics::MaskImage sharp = render(*rig, {"checkerboard=true", "checker_depth_epsilon=0.000001"});
  metrics::MaskImage blind = render(*rig, {"checkerboard=true", "checker_depth_epsilon=10"});
  ASSERT_EQ(sharp.pixels.size(), blind.pixels.size());
  size_t changed = 0;
  float largest = 0.0f;
  for (size_t i = 0; i < sharp.pixels.size(); ++i) {
    const float d = std::abs(sharp.pixels[i] - blind.pixels[i]);
    if (d > 0.01f) ++changed;
    largest = std::max(largest, d);
  }
  std::printf("[ measure  ] checker eps 1e-6 vs 10: %zu pixels differ by > 0.01, largest %.3f\n", changed, largest);
  EXPECT_GT(changed, 10u);
  EXPECT_GT(largest, 0.05f);
}

// Section 2.2: the penumbra mask approximates regular CHSS (same search, at screen/4, blurred).
// Measured RMSE between them: ball 0.02x, poles 0.03x; bound 0.05.
TEST(PmchssVariants, PenumbraMaskStaysCloseToRegularChss) {
  for (const char* name : {"ball", "poles"}) {
    test::PmchssRig rig(test::kWidth, test::kHeight, test::kShadowSize);
    rig.set_scene(test::make_scene(name));
    rig.set(test::test_settings());
    rig.set({"k=" + std::to_string(test::kCalibratedK)});
    metrics::MaskImage regular = render(rig, {"variant=regular"});
    metrics::MaskImage mask = render(rig, {"variant=penumbra_mask"});
    auto e = metrics::compare_masks(mask, regular, rig.coverage());
    ASSERT_TRUE(e);
    std::printf("[ measure  ] %s: penumbra mask vs regular CHSS RMSE %.4f\n", name, e->rmse);
    EXPECT_LT(e->rmse, 0.05) << name;
  }
}
