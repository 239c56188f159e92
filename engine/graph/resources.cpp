#include "graph/resources.h"

#include <algorithm>
#include <string>
#include <cctype>
#include <charconv>

namespace penumbra::graph {

namespace {
struct FormatFacts {
  Format format;
  const char* name;
  int bytes;
  int channels;
  const char* image_qualifier;  // "" for depth
};
constexpr FormatFacts kFormats[kFormatCount] = {
    {Format::R8, "R8", 1, 1, "r8"},
    {Format::R16F, "R16F", 2, 1, "r16f"},
    {Format::R32F, "R32F", 4, 1, "r32f"},
    {Format::RG16F, "RG16F", 4, 2, "rg16f"},
    {Format::RG32F, "RG32F", 8, 2, "rg32f"},
    {Format::RGBA8, "RGBA8", 4, 4, "rgba8"},
    {Format::RGBA16F, "RGBA16F", 8, 4, "rgba16f"},
    {Format::RGBA32F, "RGBA32F", 16, 4, "rgba32f"},
    {Format::DEPTH32F, "DEPTH32F", 4, 1, ""},
    {Format::R16, "R16", 2, 1, "r16"},
    {Format::RG16, "RG16", 4, 2, "rg16"},
    {Format::R16_SNORM, "R16_SNORM", 2, 1, "r16_snorm"},
    {Format::RG16_SNORM, "RG16_SNORM", 4, 2, "rg16_snorm"},
    {Format::RGB10A2, "RGB10A2", 4, 4, "rgb10_a2"},
    {Format::R11G11B10F, "R11G11B10F", 4, 3, "r11f_g11f_b10f"},
    {Format::RGBA16, "RGBA16", 8, 4, "rgba16"},
    {Format::RGBA16_SNORM, "RGBA16_SNORM", 8, 4, "rgba16_snorm"},
};
constexpr bool listed_in_enum_order() {
  for (int i = 0; i < kFormatCount; ++i)
    if (static_cast<int>(kFormats[i].format) != i) return false;
  return true;
}
static_assert(listed_in_enum_order(), "kFormats is indexed by Format");

bool parse_int(std::string_view s, int& out) {
  if (s.empty()) return false;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc{} && p == s.data() + s.size();
}
}  // namespace

const char* format_name(Format format) { return kFormats[static_cast<int>(format)].name; }
bool valid_tile_size(int pixels) {
  return pixels >= kMinTileSize && pixels <= kMaxTileSize && (pixels & (pixels - 1)) == 0;
}

std::uint64_t tile_list_bytes(int tiles_x, int tiles_y) {
  return kTileListHeaderBytes + kTileListEntryBytes * static_cast<std::uint64_t>(tiles_x) * static_cast<std::uint64_t>(tiles_y);
}

int bytes_per_texel(Format format) { return kFormats[static_cast<int>(format)].bytes; }
int channel_count(Format format) { return kFormats[static_cast<int>(format)].channels; }
bool is_depth_format(Format format) { return format == Format::DEPTH32F; }

std::vector<Format> colour_formats() {
  std::vector<Format> out;
  for (const auto& f : kFormats)
    if (!is_depth_format(f.format)) out.push_back(f.format);
  return out;
}
const char* image_format_qualifier(Format format) { return kFormats[static_cast<int>(format)].image_qualifier; }

std::string format_names() {
  std::string out;
  for (const auto& f : kFormats) out += (out.empty() ? "" : ", ") + std::string(f.name);
  return out;
}

std::optional<Format> parse_format(std::string_view name) {
  for (const auto& f : kFormats)
    if (name == f.name) return f.format;
  return std::nullopt;
}

const char* resource_kind_name(ResourceKind kind) {
  switch (kind) {
    case ResourceKind::texture: return "texture";
    case ResourceKind::buffer: return "buffer";
    case ResourceKind::imported: return "imported";
    case ResourceKind::persistent: return "persistent";
  }
  return "?";
}

std::optional<ResourceKind> parse_resource_kind(std::string_view name) {
  for (auto k : {ResourceKind::texture, ResourceKind::buffer, ResourceKind::imported,
                 ResourceKind::persistent})
    if (name == resource_kind_name(k)) return k;
  return std::nullopt;
}

std::optional<SizeExpr> SizeExpr::parse(std::string_view text) {
  auto with_divisor = [&](std::string_view base, Base b) -> std::optional<SizeExpr> {
    if (text == base) return SizeExpr{b, 1, 0, 0, {}};
    if (text.size() > base.size() + 1 && text.substr(0, base.size()) == base &&
        text[base.size()] == '/') {
      std::string_view divisor = text.substr(base.size() + 1);
      if (divisor.size() > 1 && divisor[0] == '$') {
        std::string_view name = divisor.substr(1);
        bool ok = std::all_of(name.begin(), name.end(), [](char c) {
          return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
        });
        if (!ok) return std::nullopt;
        return SizeExpr{b, 1, 0, 0, std::string(name)};
      }
      int div = 0;
      if (!parse_int(divisor, div) || div < 1 || div > kMaxSizeDivisor) return std::nullopt;
      return SizeExpr{b, div, 0, 0, {}};
    }
    return std::nullopt;
  };
  if (text.starts_with("screen")) return with_divisor("screen", Base::screen);
  if (text.starts_with("shadow")) return with_divisor("shadow", Base::shadow);
  size_t x = text.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  int w = 0, h = 0;
  if (!parse_int(text.substr(0, x), w) || !parse_int(text.substr(x + 1), h) || w < 1 ||
      h < 1 || w > kMaxTextureSize || h > kMaxTextureSize)
    return std::nullopt;
  return SizeExpr::fixed(w, h);
}

std::string SizeExpr::to_string() const {
  std::string div = !divisor_reference.empty() ? "/$" + divisor_reference
                    : divisor == 1             ? ""
                                               : "/" + std::to_string(divisor);
  switch (base) {
    case Base::screen: return "screen" + div;
    case Base::shadow: return "shadow" + div;
    case Base::fixed: return std::to_string(width) + "x" + std::to_string(height);
  }
  return "?";
}

void SizeExpr::resolve(const CompileSettings& s, int divisor, int& w, int& h) const {
  divisor = std::max(divisor, 1);
  switch (base) {
    case Base::screen: w = s.screen_w / divisor; h = s.screen_h / divisor; break;
    case Base::shadow: w = h = s.shadow_size / divisor; break;
    case Base::fixed: w = width; h = height; break;
  }
  w = std::max(w, 1);
  h = std::max(h, 1);
}

}  // namespace penumbra::graph
