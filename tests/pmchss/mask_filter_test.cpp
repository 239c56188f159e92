// The penumbra mask's max filter and Gaussian blur run in shared memory inside the search
// dispatch (penumbra_mask.comp.glsl). They must equal the paper's separable filters (section
// 2.2: 7x7 max, 7x7 Gaussian sigma 3) applied to the unfiltered search result with
// clamp-to-edge, which the CPU computes here from the debug copy of the raw mask (the same
// search, same noise, written without filtering).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pmchss_fixture.h"
#include "pmchss_settings.h"

using namespace penumbra;

namespace {

// One axis of a 7-tap filter with clamp-to-edge; gaussian weights exp(-t^2 / 2 sigma^2),
// normalised; otherwise max.
metrics::MaskImage filter_axis(const metrics::MaskImage& in, bool horizontal, bool gaussian, double sigma) {
  metrics::MaskImage out(in.width, in.height);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      double acc = gaussian ? 0.0 : in.at(x, y), weights = 0.0;
      for (int t = -3; t <= 3; ++t) {
        int sx = horizontal ? std::clamp(x + t, 0, in.width - 1) : x;
        int sy = horizontal ? y : std::clamp(y + t, 0, in.height - 1);
        double v = in.at(sx, sy);
        if (gaussian) {
          double w = std::exp(-double(t * t) / (2.0 * sigma * sigma));
          acc += w * v;
          weights += w;
        } else {
          acc = std::max(acc, v);
        }
      }
      out.at(x, y) = static_cast<float>(gaussian ? acc / weights : acc);
    }
  return out;
}

double max_difference(const metrics::MaskImage& a, const metrics::MaskImage& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) worst = std::max(worst, double(std::abs(a.pixels[i] - b.pixels[i])));
  return worst;
}

}  // namespace

// Every filter combination at both mask sizes (56x42 and 112x84 texels: no multiple of the
// 26- or 20-texel blocks a workgroup writes with one or two filter stages, so partial blocks
// and all four image edges are covered). R16F
// storage of the raw copy and of the result bounds the difference: half a 16-bit ulp at 1.0 is
// 0.0005 per value; the bound 0.002 allows the rounding of both plus fp32 reordering.
TEST(PmchssMaskFilter, FusedFiltersEqualSeparableFiltersOfTheRawMask) {
  test::PmchssRig rig(test::kWidth, test::kHeight, test::kShadowSize);
  rig.set_scene(test::make_scene("poles"));
  rig.set(test::test_settings());
  rig.set({"k=" + std::to_string(test::kCalibratedK), "variant=penumbra_mask", "debug_outputs=true",
           "mask_blur_sigma=2.5"});
  struct Case { bool blur, max; };
  for (const char* divisor : {"4", "2"}) {
    for (Case c : {Case{true, false}, Case{true, true}, Case{false, true}}) {
      rig.set({std::string("mask_divisor=") + divisor, std::string("mask_blur=") + (c.blur ? "true" : "false"),
               std::string("mask_max_filter=") + (c.max ? "true" : "false")});
      rig.render();
      metrics::MaskImage raw = rig.read("penumbra_mask_raw");
      metrics::MaskImage fused = rig.read("penumbra_mask");
      ASSERT_EQ(raw.width, test::kWidth / std::stoi(divisor));
      ASSERT_GT(raw.width, 0);
      ASSERT_EQ(raw.width, fused.width);
      size_t penumbra = std::count_if(raw.pixels.begin(), raw.pixels.end(), [](float v) { return v > 0.05f; });
      ASSERT_GT(penumbra, raw.pixels.size() / 50) << "the raw mask must hold penumbrae to filter";

      metrics::MaskImage expected = raw;
      if (c.max) expected = filter_axis(filter_axis(expected, true, false, 0), false, false, 0);
      if (c.blur) expected = filter_axis(filter_axis(expected, true, true, 2.5), false, true, 2.5);
      double diff = max_difference(fused, expected);
      double change = max_difference(raw, expected);
      std::printf("[ measure  ] screen/%s blur=%d max=%d: %zu penumbra texels, max |fused - CPU| %.5f "
                  "(filter changes up to %.3f)\n", divisor, c.blur, c.max, penumbra, diff, change);
      EXPECT_LT(diff, 0.002) << "screen/" << divisor << " blur " << c.blur << " max " << c.max;
      EXPECT_GT(change, 0.1) << "the filters must change the mask for the comparison to mean anything";
    }
  }
}
