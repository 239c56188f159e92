// The reference cache's format: what is written reads back equal, and every kind of damage is
// refused with its reason instead of yielding NaN metrics.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "metrics/reference_cache_file.h"

namespace penumbra::metrics {
namespace {

struct Entry {
  std::string key = "scene ball\ncamera 1 2 3";
  MaskImage mask{4, 3};
  CoverageMask coverage = CoverageMask(12, 1);
  Entry() {
    for (size_t i = 0; i < mask.pixels.size(); ++i) mask.pixels[i] = static_cast<float>(i) / 11.0f;
    coverage[5] = 0;
  }
  std::string bytes() const { return format_reference_cache(key, mask, coverage); }
  size_t pixel_offset(size_t i) const { return 8 + 4 + key.size() + 8 + i * 4; }
};

std::string why(const Result<CachedReference>& r) { return r ? "" : r.error().message; }

TEST(ReferenceCacheFile, WhatIsWrittenReadsBackEqual) {
  const Entry e;
  const std::string bytes = e.bytes();
  EXPECT_EQ(bytes.size(), reference_cache_size(e.key, 4, 3));
  Result<CachedReference> r = parse_reference_cache(bytes, e.key, 4, 3);
  ASSERT_TRUE(r) << why(r);
  EXPECT_EQ(r->mask.pixels, e.mask.pixels);
  EXPECT_EQ(r->coverage, e.coverage);
}

TEST(ReferenceCacheFile, EveryKindOfDamageIsRefusedWithItsReason) {
  const Entry e;
  const std::string good = e.bytes();
  auto with_pixel = [&](size_t i, float v) {
    std::string b = good;
    std::memcpy(b.data() + e.pixel_offset(i), &v, 4);
    return b;
  };
  std::string bad_coverage = good;
  bad_coverage[bad_coverage.size() - 1] = 7;
  const struct {
    std::string bytes;
    int w, h;
    std::string reason;
  } cases[] = {
      {"garbage", 4, 3, "not a reference cache file"},
      {good.substr(0, 30), 4, 3, "truncated"},
      {good.substr(0, good.size() - 1), 4, 3, "truncated or damaged"},
      {good + "x", 4, 3, "truncated or damaged"},
      {good, 3, 4, "it is 4x3, the frame 3x4"},
      {with_pixel(2, std::numeric_limits<float>::quiet_NaN()), 4, 3, "pixel (2, 0) is not a visibility"},
      {with_pixel(7, 3.0f), 4, 3, "pixel (3, 1) is not a visibility"},
      {with_pixel(0, -0.5f), 4, 3, "pixel (0, 0)"},
      {bad_coverage, 4, 3, "coverage is damaged"},
  };
  for (const auto& c : cases) {
    bool other_frame = true;
    Result<CachedReference> r = parse_reference_cache(c.bytes, e.key, c.w, c.h, &other_frame);
    ASSERT_FALSE(r) << c.reason;
    EXPECT_NE(why(r).find(c.reason), std::string::npos) << why(r) << " (wanted " << c.reason << ")";
    EXPECT_FALSE(other_frame);
  }
}

TEST(ReferenceCacheFile, AnotherFramesEntryIsNoDamage) {
  const Entry e;
  bool other_frame = false;
  Result<CachedReference> r = parse_reference_cache(e.bytes(), e.key + " other", 4, 3, &other_frame);
  ASSERT_FALSE(r);
  EXPECT_TRUE(other_frame);
}

TEST(ReferenceCacheFile, RoundingPastOneIsAccepted) {
  Entry e;
  e.mask.pixels[0] = 1.0f + 1e-5f;
  EXPECT_TRUE(parse_reference_cache(e.bytes(), e.key, 4, 3));
}

}  // namespace
}  // namespace penumbra::metrics
