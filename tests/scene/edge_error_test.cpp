// The edge error (metrics/edge_error.h): mean |test - reference| within 3 px of a reference edge.
#include <gtest/gtest.h>

#include "metrics/edge_error.h"
#include "metrics/mask_metrics.h"

using namespace penumbra;
using metrics::MaskImage;

namespace {

// 40 x 30, shadow (0) left of column `edge`, lit (1) from it on.
MaskImage vertical_edge(int edge) {
  MaskImage m(40, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) m.at(x, y) = x < edge ? 0.0f : 1.0f;
  return m;
}

}  // namespace

TEST(EdgeError, BandIsThreePixelsEitherSideOfTheEdge) {
  const MaskImage ref = vertical_edge(20);
  const metrics::CoverageMask band = metrics::edge_band(ref);
  size_t count = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      const bool in = band[static_cast<size_t>(y) * 40 + x] != 0;
      count += in;
      // Edge pixels are columns 19 and 20 (each differs from a neighbour); +-3 around them.
      EXPECT_EQ(in, x >= 16 && x <= 23) << x << "," << y;
    }
  EXPECT_EQ(count, 8u * 30u);
}

TEST(EdgeError, IsTheMeanErrorOverTheBandOnly) {
  const MaskImage ref = vertical_edge(20);
  Result<metrics::EdgeError> same = metrics::edge_error(ref, ref);
  ASSERT_TRUE(same);
  EXPECT_EQ(same->error, 0.0);
  MaskImage shifted = vertical_edge(21);  // column 20 wrong: 30 of 240 band pixels off by 1
  shifted.at(3, 3) = 0.5f;                // far from the edge: not counted
  Result<metrics::EdgeError> e = metrics::edge_error(shifted, ref);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->pixels, 240u);
  EXPECT_DOUBLE_EQ(e->error, 30.0 / 240.0);
  // compare_masks reports the same number.
  Result<metrics::MaskErrors> all = metrics::compare_masks(shifted, ref);
  ASSERT_TRUE(all);
  EXPECT_DOUBLE_EQ(all->edge_error, e->error);
  EXPECT_EQ(all->edge_pixels, 240u);
}

TEST(EdgeError, FractionalReferencePixelsAreEdgesAndBackgroundIsNot) {
  MaskImage ref(40, 30, 1.0f);
  ref.at(10, 10) = 0.6f;  // anti-aliased (fractional), yet on the lit side of 0.5 like its neighbours
  metrics::CoverageMask cov(ref.pixels.size(), 1);
  for (int y = 0; y < 30; ++y) cov[static_cast<size_t>(y) * 40 + 30] = 0;  // background column
  MaskImage dark = ref;
  for (int y = 0; y < 30; ++y) dark.at(31, y) = 0.0f;  // no reference edge there: not counted
  const metrics::CoverageMask band = metrics::edge_band(ref, cov);
  size_t count = 0;
  for (uint8_t b : band) count += b;
  EXPECT_EQ(count, 29u);  // the disk of radius 3 around (10, 10)
  Result<metrics::EdgeError> e = metrics::edge_error(dark, ref, cov);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->error, 0.0);
}

TEST(EdgeError, NoEdgeMeansAnEmptyBandAndSizeMismatchIsAnError) {
  const MaskImage lit(20, 10, 1.0f);
  Result<metrics::EdgeError> e = metrics::edge_error(lit, lit);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->pixels, 0u);
  EXPECT_EQ(e->error, 0.0);
  EXPECT_FALSE(metrics::edge_error(lit, MaskImage(10, 10, 1.0f)));
}
