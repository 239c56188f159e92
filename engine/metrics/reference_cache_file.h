#pragma once
// The reference cache's file format (measurement/reference_frame.h keeps the cache): one
// finished reference mask and its receiver coverage, with the text key of everything that
// decided it. GL-free, so the fuzz target reads it as eval does.
//
//   "PNMBREF1" | u32 key bytes | key | u32 width | u32 height | width*height f32 mask
//   | width*height u8 coverage (0 or 1)          (little-endian, nothing after)
//
//   bool other_frame = false;
//   Result<CachedReference> r = parse_reference_cache(bytes, key, 640, 360, &other_frame);
//   if (!r && !other_frame) warn that the file is damaged, then render again
#include <string>
#include <string_view>

#include "metrics/mask_image.h"
#include "util/error.h"

namespace penumbra::metrics {

struct CachedReference {
  MaskImage mask;         // every pixel finite and in [0, 1] (within float rounding)
  CoverageMask coverage;  // every entry 0 or 1
};

// Bytes of a cache file for `key` at width x height (the largest file parse accepts for them).
size_t reference_cache_size(const std::string& key, int width, int height);

// The cache entry in `bytes`, or why it cannot be used. `other_frame` is set when the file is
// whole but was written for another key (a hash collision, not damage).
Result<CachedReference> parse_reference_cache(std::string_view bytes, const std::string& key, int width, int height,
                                              bool* other_frame = nullptr);

std::string format_reference_cache(const std::string& key, const MaskImage& mask, const CoverageMask& coverage);

}  // namespace penumbra::metrics
