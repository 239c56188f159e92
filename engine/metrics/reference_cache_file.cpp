#include "metrics/reference_cache_file.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace penumbra::metrics {

namespace {

constexpr char kMagic[8] = {'P', 'N', 'M', 'B', 'R', 'E', 'F', '1'};
constexpr std::uint32_t kMaxKeyBytes = 1u << 20;
// A visibility summed from many samples may pass 1 by float rounding; garbage passes it by far.
constexpr float kRounding = 1e-3f;

class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}
  bool u32(std::uint32_t& v) { return take(&v, 4); }
  bool take(void* out, size_t n) {
    if (bytes_.size() - pos_ < n) return false;
    std::memcpy(out, bytes_.data() + pos_, n);
    pos_ += n;
    return true;
  }
  std::string_view view(size_t n) {
    if (bytes_.size() - pos_ < n) return {};
    std::string_view v = bytes_.substr(pos_, n);
    pos_ += n;
    return v;
  }
  size_t left() const { return bytes_.size() - pos_; }

 private:
  std::string_view bytes_;
  size_t pos_ = 0;
};

}  // namespace

size_t reference_cache_size(const std::string& key, int width, int height) {
  const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
  return sizeof kMagic + 4 + key.size() + 8 + pixels * 5;
}

Result<CachedReference> parse_reference_cache(std::string_view bytes, const std::string& key, int width, int height,
                                              bool* other_frame) {
  if (other_frame) *other_frame = false;
  ByteReader in(bytes);
  char magic[8];
  if (!in.take(magic, 8) || std::memcmp(magic, kMagic, 8) != 0) return make_error("not a reference cache file");
  std::uint32_t key_size = 0, w = 0, h = 0;
  if (!in.u32(key_size) || key_size > kMaxKeyBytes) return make_error("its key length is damaged");
  const std::string_view stored = in.view(key_size);
  if (stored.size() != key_size) return make_error("it is truncated (in its key)");
  if (stored != key) {
    if (other_frame) *other_frame = true;
    return make_error("it holds the reference of another frame");
  }
  if (!in.u32(w) || !in.u32(h)) return make_error("it is truncated (before its size)");
  if (static_cast<int64_t>(w) != width || static_cast<int64_t>(h) != height)
    return make_error("it is " + std::to_string(w) + "x" + std::to_string(h) + ", the frame " + std::to_string(width) +
                      "x" + std::to_string(height));
  const size_t pixels = static_cast<size_t>(w) * h;
  if (in.left() != pixels * 5)
    return make_error("it holds " + std::to_string(in.left()) + " bytes of pixels, " + std::to_string(pixels * 5) +
                      " expected (truncated or damaged)");
  CachedReference out{MaskImage(width, height), CoverageMask(pixels)};
  in.take(out.mask.pixels.data(), pixels * 4);
  in.take(out.coverage.data(), pixels);
  for (size_t i = 0; i < pixels; ++i) {
    const float v = out.mask.pixels[i];
    if (!std::isfinite(v) || v < -kRounding || v > 1.0f + kRounding)
      return make_error("pixel (" + std::to_string(i % w) + ", " + std::to_string(i / w) +
                        ") is not a visibility in [0, 1]");
    if (out.coverage[i] > 1) return make_error("its coverage is damaged");
  }
  return out;
}

std::string format_reference_cache(const std::string& key, const MaskImage& mask, const CoverageMask& coverage) {
  std::string bytes(kMagic, 8);
  auto put32 = [&](std::uint32_t v) { bytes.append(reinterpret_cast<const char*>(&v), 4); };
  put32(static_cast<std::uint32_t>(key.size()));
  bytes += key;
  put32(static_cast<std::uint32_t>(mask.width));
  put32(static_cast<std::uint32_t>(mask.height));
  bytes.append(reinterpret_cast<const char*>(mask.pixels.data()), mask.pixels.size() * 4);
  bytes.append(reinterpret_cast<const char*>(coverage.data()), coverage.size());
  return bytes;
}

}  // namespace penumbra::metrics
