#include <filesystem>

#include <gtest/gtest.h>

#include "test_support/temp_dir.h"

#include "metrics/heat_map.h"
#include "metrics/mask_metrics.h"
#include "metrics/penumbra_width.h"

using namespace penumbra;
using metrics::MaskImage;

static MaskImage pattern(int w, int h) {
  MaskImage m(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.at(x, y) = 0.5f + 0.4f * std::sin(0.3f * x) * std::cos(0.2f * y);
  return m;
}

TEST(Metrics, IdenticalImagesHaveNoError) {
  const MaskImage a = pattern(40, 30);
  Result<metrics::MaskErrors> e = metrics::compare_masks(a, a);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->rmse, 0.0);
  EXPECT_EQ(e->mae, 0.0);
  EXPECT_EQ(e->max_error, 0.0);
  EXPECT_NEAR(e->ssim, 1.0, 1e-9);
  EXPECT_EQ(e->pixels, 1200u);
}

TEST(Metrics, ConstantOffsetGivesThatOffsetAndBackgroundIsExcluded) {
  const MaskImage ref = pattern(40, 30);
  MaskImage test = ref;
  for (float& v : test.pixels) v += 0.05f;
  metrics::CoverageMask cov(ref.pixels.size(), 1);
  for (int x = 0; x < 40; ++x) {  // background row with a huge error that must not count
    cov[static_cast<size_t>(x)] = 0;
    test.at(x, 0) = 100.0f;
  }
  Result<metrics::MaskErrors> e = metrics::compare_masks(test, ref, cov);
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->rmse, 0.05, 1e-6);
  EXPECT_NEAR(e->mae, 0.05, 1e-6);
  EXPECT_NEAR(e->max_error, 0.05, 1e-6);
  EXPECT_NEAR(e->rmse_penumbra, 0.05, 1e-6);
  EXPECT_EQ(e->pixels, 1200u - 40u);
  EXPECT_LT(e->ssim, 1.0);
  EXPECT_GT(e->ssim, 0.9);
  EXPECT_FALSE(metrics::compare_masks(MaskImage(3, 3), MaskImage(4, 3)));
}

TEST(Metrics, PenumbraWidthOfALinearRamp) {
  MaskImage m(100, 5);
  const float a = 30.0f, width = 20.0f;  // ramp 0 -> 1 from x = 30 to x = 50 (pixel-centre coordinates)
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 100; ++x) m.at(x, y) = std::clamp((x + 0.5f - a) / width, 0.0f, 1.0f);
  Result<float> w = metrics::penumbra_width(m, {2.5f, 2.5f}, {97.5f, 2.5f});
  ASSERT_TRUE(w) << w.error().to_string();
  EXPECT_NEAR(*w, width, 1.0f);
  // The 0.02 -> 0.98 definition gives 0.96 W; bilinear sampling rounds the ramp's kinks by
  // up to 0.1 px at each end.
  EXPECT_NEAR(*w, 0.96f * width, 0.25f);
  Result<float> back = metrics::penumbra_width(m, {97.5f, 2.5f}, {2.5f, 2.5f});  // falling probe
  ASSERT_TRUE(back);
  EXPECT_NEAR(*back, *w, 1e-3f);
  EXPECT_FALSE(metrics::penumbra_width(MaskImage(10, 10, 1.0f), {0.5f, 0.5f}, {9.5f, 0.5f}));
}

TEST(Metrics, HeatMapAndPngWrite) {
  const MaskImage ref = pattern(16, 8);
  MaskImage test = ref;
  test.at(3, 3) += 1.0f;
  Result<metrics::RgbaImage> map = metrics::error_heat_map(test, ref, {}, 1.0f);
  ASSERT_TRUE(map);
  EXPECT_EQ(map->pixels[(3 * 16 + 3) * 4 + 0], 255);  // max error -> white
  EXPECT_EQ(map->pixels[0], 0);                      // zero error -> black
  const auto dir = test::fresh_temp_dir("metrics_test");
  EXPECT_TRUE(metrics::write_png((dir / "heat.png").string(), *map));
  EXPECT_TRUE(metrics::write_png((dir / "mask.png").string(), ref));
  EXPECT_GT(std::filesystem::file_size(dir / "heat.png"), 50u);
  const std::string bad = (dir / "no_such_dir" / "x.png").string();
  Status s = metrics::write_png(bad, ref);
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().file, bad);
  EXPECT_FALSE(std::filesystem::exists(bad));
  std::filesystem::remove_all(dir);
}
