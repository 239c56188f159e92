// The pixel classes of the penumbra metric (metrics/pixel_classes.h) on synthetic frames: a plane
// has no geometric edge however it is tilted; a depth step, a fold of the normal, the background
// and a self-shadowing terminator each make a band kGeometricEdgeRadius px wide; the soft
// penumbra is the reference's fractional pixels elsewhere; the reliability rule; and
// compare_masks splitting its errors by class and leaving out receivers the light does not reach.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "metrics/mask_metrics.h"
#include "metrics/pixel_classes.h"

using namespace penumbra::metrics;
using penumbra::Result;

namespace {

constexpr int kW = 40, kH = 30;

// A frame whose pixel (x, y) has inverse view depth inv(x, y) (a plane when linear in x and y),
// normal n(x, y), facing f(x, y) and is reached by the light where `reached`; inv <= 0 is background.
ReceiverGeometry geometry(const std::function<float(int, int)>& inv,
                          const std::function<glm::vec3(int, int)>& n = [](int, int) { return glm::vec3(0, 1, 0); },
                          const std::function<float(int, int)>& f = [](int, int) { return 1.0f; },
                          const std::function<bool(int, int)>& reached = [](int, int) { return true; }) {
  ReceiverGeometry g{kW, kH, {}, {}, {}, {}};
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const float i = inv(x, y);
      g.view_depth.push_back(i > 0.0f ? 1.0f / i : 0.0f);
      g.normals.push_back(n(x, y));
      g.facing.push_back(f(x, y));
      g.reached.push_back(reached(x, y));
    }
  return g;
}

CoverageMask coverage_of(const ReceiverGeometry& g) {
  CoverageMask c;
  for (float d : g.view_depth) c.push_back(d > 0.0f);
  return c;
}

// Columns of geometric-edge pixels on row y.
std::vector<int> edge_columns(const PixelClasses& c, int y) {
  std::vector<int> out;
  for (int x = 0; x < kW; ++x)
    if (c.classes[static_cast<size_t>(y) * kW + x] == PixelClass::geometric_edge) out.push_back(x);
  return out;
}

const MaskImage kLit(kW, kH, 1.0f);

}  // namespace

TEST(PixelClasses, ATiltedPlaneHasNoGeometricEdge) {
  // Inverse depth linear in x and y: a plane seen in perspective, steep (depth 2 to 14).
  const ReceiverGeometry g = geometry([](int x, int y) { return 0.5f - 0.008f * x - 0.004f * y; });
  const PixelClasses c = classify_pixels(kLit, coverage_of(g), &g);
  EXPECT_EQ(c.count(PixelClass::geometric_edge), 0u);
  EXPECT_EQ(c.count(PixelClass::lit), static_cast<size_t>(kW) * kH);
}

TEST(PixelClasses, ADepthStepMarksABandAsWideAsTheRadiusOnBothSides) {
  // Depth 2 left of x = 20, 4 from x = 20 on: the step is between columns 19 and 20.
  const ReceiverGeometry g = geometry([](int x, int) { return x < 20 ? 0.5f : 0.25f; });
  const PixelClasses c = classify_pixels(kLit, coverage_of(g), &g);
  const int r = kGeometricEdgeRadius;
  std::vector<int> expected;
  for (int x = 19 - r; x <= 20 + r; ++x) expected.push_back(x);
  for (int y : {0, 15, kH - 1}) EXPECT_EQ(edge_columns(c, y), expected) << "row " << y;
}

TEST(PixelClasses, AFoldOfTheNormalIsAnEdgeAGentleCurveIsNot) {
  const auto plane = [](int, int) { return 0.25f; };
  const ReceiverGeometry fold = geometry(plane, [](int x, int) {
    return x < 20 ? glm::vec3(0, 1, 0) : glm::normalize(glm::vec3(1, 1, 0));  // 45 degrees
  });
  EXPECT_EQ(edge_columns(classify_pixels(kLit, coverage_of(fold), &fold), 5).size(), 2u + 2 * kGeometricEdgeRadius);
  const ReceiverGeometry curve = geometry(plane, [](int x, int) {
    const float a = 0.02f * static_cast<float>(x);  // about 1 degree a pixel
    return glm::vec3(std::sin(a), std::cos(a), 0.0f);
  });
  EXPECT_TRUE(edge_columns(classify_pixels(kLit, coverage_of(curve), &curve), 5).empty());
}

TEST(PixelClasses, TheTerminatorAndTheBackgroundAreEdges) {
  const auto plane = [](int, int) { return 0.25f; };
  const ReceiverGeometry terminator =
      geometry(plane, [](int, int) { return glm::vec3(0, 1, 0); }, [](int x, int) { return x < 30 ? 0.3f : -0.1f; });
  EXPECT_EQ(edge_columns(classify_pixels(kLit, coverage_of(terminator), &terminator), 10),
            (std::vector<int>{27, 28, 29, 30, 31, 32})) << "both sides of the sign change";
  const ReceiverGeometry half = geometry([](int x, int) { return x < 10 ? 0.0f : 0.25f; });  // background left
  const PixelClasses c = classify_pixels(kLit, coverage_of(half), &half);
  EXPECT_EQ(edge_columns(c, 10), (std::vector<int>{10, 11, 12}));
  EXPECT_EQ(c.classes[10 * kW + 3], PixelClass::background);
}

TEST(PixelClasses, SoftPenumbraIsTheFractionalReferenceAwayFromEdges) {
  const ReceiverGeometry g = geometry([](int x, int) { return x < 20 ? 0.5f : 0.25f; });
  MaskImage ref(kW, kH, 1.0f);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) ref.at(x, y) = y < 10 ? 0.0f : (y < 20 ? 0.5f : 1.0f);
  const PixelClasses c = classify_pixels(ref, coverage_of(g), &g);
  EXPECT_EQ(c.classes[5 * kW + 5], PixelClass::umbra);
  EXPECT_EQ(c.classes[15 * kW + 5], PixelClass::soft_penumbra);
  EXPECT_EQ(c.classes[25 * kW + 5], PixelClass::lit);
  EXPECT_EQ(c.classes[15 * kW + 20], PixelClass::geometric_edge) << "the step wins over the penumbra";
  const PixelClasses by_reference = classify_pixels(ref, coverage_of(g));
  EXPECT_EQ(by_reference.classes[15 * kW + 20], PixelClass::soft_penumbra) << "no G-buffer, no geometric edge";
  EXPECT_EQ(by_reference.count(PixelClass::geometric_edge), 0u);
}

TEST(PixelClasses, ReliabilityNeedsOnePercentOfReceiversInGroups) {
  MaskImage ref(kW, kH, 1.0f);
  CoverageMask all(static_cast<size_t>(kW) * kH, 1);
  EXPECT_EQ(penumbra_reliability(classify_pixels(ref, all)).reason, "no soft penumbra");
  ref.at(3, 3) = 0.5f;  // 1 of 1200 pixels
  const PenumbraReliability few = penumbra_reliability(classify_pixels(ref, all));
  EXPECT_FALSE(few.reliable);
  EXPECT_NE(few.reason.find("under 1%"), std::string::npos) << few.reason;
  // 20 isolated pixels (1.7%): mostly single-pixel groups.
  for (int i = 0; i < 20; ++i) ref.at(2 + 2 * (i % 10), 10 + 2 * (i / 10)) = 0.5f;
  const PenumbraReliability specks = penumbra_reliability(classify_pixels(ref, all));
  EXPECT_FALSE(specks.reliable);
  EXPECT_EQ(specks.groups, 21u);
  EXPECT_EQ(specks.single_pixel_groups, 21u);
  EXPECT_NE(specks.reason.find("single pixels"), std::string::npos) << specks.reason;
  // A band 3 rows high: one group, reliable.
  for (int y = 20; y < 23; ++y)
    for (int x = 0; x < kW; ++x) ref.at(x, y) = 0.5f;
  const PenumbraReliability band = penumbra_reliability(classify_pixels(ref, all));
  EXPECT_EQ(band.groups, 22u);
  EXPECT_FALSE(band.reliable) << "21 of 22 groups are still specks";
  ref = MaskImage(kW, kH, 1.0f);
  for (int y = 20; y < 23; ++y)
    for (int x = 0; x < kW; ++x) ref.at(x, y) = 0.5f;
  EXPECT_TRUE(penumbra_reliability(classify_pixels(ref, all)).reliable);
}

TEST(PixelClasses, CompareMasksSplitsTheErrorByClass) {
  const ReceiverGeometry g = geometry([](int x, int) { return x < 20 ? 0.5f : 0.25f; });
  MaskImage ref(kW, kH, 0.5f);  // all penumbra by value
  MaskImage test = ref;
  for (int y = 0; y < kH; ++y) test.at(20, y) = 0.9f;  // wrong on the step only
  const CoverageMask cov = coverage_of(g);
  const PixelClasses c = classify_pixels(ref, cov, &g);
  Result<MaskErrors> e = compare_masks(test, ref, cov, c);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->rmse_penumbra, 0.0) << "the soft penumbra is exact";
  EXPECT_EQ(e->penumbra_pixels, static_cast<size_t>(kW - 2 - 2 * kGeometricEdgeRadius) * kH);
  EXPECT_EQ(e->geometric_edge_pixels, static_cast<size_t>(2 + 2 * kGeometricEdgeRadius) * kH);
  EXPECT_NEAR(e->rmse_geometric_edge, 0.4 / std::sqrt(2.0 + 2 * kGeometricEdgeRadius), 1e-6);
  Result<MaskErrors> by_value = compare_masks(test, ref, cov);
  ASSERT_TRUE(by_value);
  EXPECT_GT(by_value->rmse_penumbra, 0.0) << "without the G-buffer the step's error is penumbra error";
}

// A spot's cone ends at column 30: beyond it the lighting shows no mask value, so a technique
// that calls those receivers lit where the truth has umbra (a shadow map ends at its frustum) is
// not wrong, and nothing counts them, not even the penumbra's share of the receivers.
TEST(PixelClasses, ReceiversOutsideTheLightAreJudgedByNothing) {
  const ReceiverGeometry g = geometry([](int, int) { return 0.25f; }, [](int, int) { return glm::vec3(0, 1, 0); },
                                      [](int, int) { return 1.0f; }, [](int x, int) { return x < 30; });
  MaskImage ref(kW, kH, 1.0f);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (x >= 30) ref.at(x, y) = 0.0f;            // umbra outside the cone
      if (y >= 10 && y < 13) ref.at(x, y) = 0.5f;  // a band of penumbra across the whole frame
    }
  MaskImage test = ref;
  for (int y = 0; y < kH; ++y)
    for (int x = 30; x < kW; ++x) test.at(x, y) = 1.0f;
  const CoverageMask cov = coverage_of(g);
  const PixelClasses c = classify_pixels(ref, cov, &g);
  EXPECT_EQ(c.count(PixelClass::outside_light), static_cast<size_t>(10 * kH));
  EXPECT_EQ(c.count(PixelClass::geometric_edge), 0u) << "the cone's edge is no edge of the geometry";
  EXPECT_EQ(c.count(PixelClass::soft_penumbra), static_cast<size_t>(30 * 3));
  Result<MaskErrors> e = compare_masks(test, ref, cov, c);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->pixels, static_cast<size_t>(30 * kH));
  EXPECT_EQ(e->rmse, 0.0);
  EXPECT_EQ(e->max_error, 0.0);
  EXPECT_EQ(e->ssim, 1.0);
  EXPECT_EQ(e->edge_error, 0.0);
  const CoverageMask judged = judged_pixels(c);
  EXPECT_EQ(std::count(judged.begin(), judged.end(), uint8_t{1}), 30 * kH);
  // 90 of 900 judged receivers are penumbra (10%); counted over all 1200 it would be 7.5%.
  EXPECT_TRUE(penumbra_reliability(c).reliable);
  // Without the G-buffer nothing is known of the light: every receiver is judged.
  Result<MaskErrors> by_value = compare_masks(test, ref, cov);
  ASSERT_TRUE(by_value);
  EXPECT_EQ(by_value->pixels, static_cast<size_t>(kW * kH));
  EXPECT_GT(by_value->rmse, 0.4);
}
