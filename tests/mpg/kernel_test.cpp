// The multi-pass kernels on the CPU (techniques/mpg/passes/multipass_kernel.h): the Poisson disk
// of section 3.1, the per-pass kernel sizes, the normalised Gaussian taps and the
// variance the physical mapping inverts. No GL.
#include <gtest/gtest.h>

#include <cmath>

#include "techniques/mpg/passes/multipass_kernel.h"

using namespace penumbra::mpg;

// Section 3.1: 64 points in [-1, 1]^2, the first at the origin, then a Poisson-like distribution
// whose every prefix keeps its points apart (tests/sampling checks the spacing of such sequences).
TEST(MpgKernel, PoissonDiskStartsAtTheOriginInsideTheSquare) {
  const auto& p = poisson_points();
  ASSERT_EQ(p.size(), static_cast<size_t>(kMaxPoissonPoints));
  EXPECT_EQ(p[0], glm::vec2(0.0f));
  for (const glm::vec2& q : p) {
    EXPECT_LE(std::abs(q.x), 1.0f);
    EXPECT_LE(std::abs(q.y), 1.0f);
  }
  EXPECT_EQ(&poisson_points(), &p);  // generated once
}

// Figure 5G: "Each successive pass increased the kernel size starting from 3x3 ... up to 19x19".
TEST(MpgKernel, ProgressiveKernelGrowsFromThreeToTheMaximum) {
  EXPECT_EQ(pass_kernel_size(true, 0, 19), 3);
  EXPECT_EQ(pass_kernel_size(true, 1, 19), 5);
  EXPECT_EQ(pass_kernel_size(true, 8, 19), 19);
  EXPECT_EQ(pass_kernel_size(true, 9, 19), 19);
  EXPECT_EQ(pass_kernel_size(false, 0, 19), 19);
  EXPECT_EQ(pass_kernel_size(false, 5, 29), 29);
}

// Taps: the first N Poisson points scaled to the kernel's outer texel centres, Gaussian weights
// (sigma = size / 3) normalised; dense: every texel. The variance grows with the kernel and, for a
// dense kernel, matches the truncated Gaussian's (computed here independently).
TEST(MpgKernel, TapsAreNormalisedGaussiansOverTheKernel) {
  for (int size : {3, 9, 19, 29}) {
    for (int count : {1, 5, 20, 64}) {
      std::vector<Tap> taps = kernel_taps(KernelSampling::poisson, count, size);
      ASSERT_EQ(taps.size(), static_cast<size_t>(count));
      EXPECT_EQ(taps[0].offset, glm::vec2(0.0f));
      double sum = 0.0;
      for (const Tap& t : taps) {
        sum += t.weight;
        EXPECT_LE(std::abs(t.offset.x), 0.5f * (size - 1) + 1e-4f);
        EXPECT_LE(std::abs(t.offset.y), 0.5f * (size - 1) + 1e-4f);
      }
      EXPECT_NEAR(sum, 1.0, 1e-5);
    }
    std::vector<Tap> dense = kernel_taps(KernelSampling::dense, 0, size);
    ASSERT_EQ(dense.size(), static_cast<size_t>(size * size));
    const double sigma = size / 3.0;
    double w = 0.0, wx2 = 0.0;
    for (int x = -(size - 1) / 2; x <= (size - 1) / 2; ++x) {
      const double g = std::exp(-x * x / (2.0 * sigma * sigma));
      w += g;
      wx2 += g * x * x;
    }
    EXPECT_NEAR(kernel_variance(dense), wx2 / w, 1e-4) << size;
  }
  EXPECT_LT(kernel_variance(kernel_taps(KernelSampling::poisson, 20, 3)),
            kernel_variance(kernel_taps(KernelSampling::poisson, 20, 19)));
  EXPECT_EQ(kernel_variance(kernel_taps(KernelSampling::poisson, 1, 19)), 0.0);  // the origin alone
}

TEST(MpgKernel, CumulativeVarianceIncreasesPassByPass) {
  std::vector<float> v = cumulative_pass_variance(KernelSampling::poisson, 20, true, 19, 10);
  ASSERT_EQ(v.size(), 11u);
  EXPECT_EQ(v[0], 0.0f);
  for (size_t i = 1; i < v.size(); ++i) EXPECT_GT(v[i], v[i - 1]) << i;
  // Fixed 19x19 passes add the same variance each time.
  std::vector<float> f = cumulative_pass_variance(KernelSampling::poisson, 20, false, 19, 4);
  EXPECT_NEAR(f[4], 4.0f * f[1], 1e-3f * f[4]);
}

// Pass i's Poisson set is pass 0's turned by i golden angles: the same radii and weights (so the
// same spread), other directions, so ten passes do not repeat one set's gaps.
TEST(MpgKernel, EachPassTurnsThePoissonSetByTheGoldenAngle) {
  const std::vector<Tap> first = kernel_taps(KernelSampling::poisson, 20, 19, 0);
  const std::vector<Tap> second = kernel_taps(KernelSampling::poisson, 20, 19, 1);
  ASSERT_EQ(first.size(), second.size());
  const float golden = 2.39996323f;
  for (size_t i = 0; i < first.size(); ++i) {
    EXPECT_NEAR(glm::length(first[i].offset), glm::length(second[i].offset), 1e-4f) << i;
    EXPECT_NEAR(first[i].weight, second[i].weight, 1e-6f) << i;
    if (glm::length(first[i].offset) < 1e-3f) continue;  // the origin
    const float turned = std::atan2(second[i].offset.y, second[i].offset.x) - std::atan2(first[i].offset.y, first[i].offset.x);
    EXPECT_NEAR(std::remainder(turned - golden, 2.0f * 3.14159265f), 0.0f, 1e-4f) << i;
  }
  // Turning changes only the bilinear term of the spread: passes of one size add nearly one variance.
  EXPECT_NEAR(kernel_variance(second), kernel_variance(first), 0.02 * kernel_variance(first));
}
