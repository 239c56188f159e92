// Reference cache files through the reader eval uses (metrics/reference_cache_file.h): for the
// frame the fuzzer's bytes claim and for a fixed one, so sizes that match and sizes that do not
// are both reached.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>

#include "metrics/reference_cache_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::string key = "fuzz";
  bool other_frame = false;
  (void)penumbra::metrics::parse_reference_cache(bytes, key, 4, 3, &other_frame);
  // The size the file states after a 4-byte key, when it is small enough to be a frame.
  if (size >= 24) {
    std::uint32_t w = 0, h = 0;
    std::memcpy(&w, data + 16, 4);
    std::memcpy(&h, data + 20, 4);
    if (w > 0 && h > 0 && w <= 256 && h <= 256)
      (void)penumbra::metrics::parse_reference_cache(bytes, key, static_cast<int>(w), static_cast<int>(h), &other_frame);
  }
  return 0;
}
