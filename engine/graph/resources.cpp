#include "graph/resources.h"

#include <algorithm>
#include <string>
#include <cctype>
#include <charconv>

namespace penumbra::graph {

namespace {
struct FormatInfo {
  Format format;
  const char* name;
  int bytes;
};
constexpr FormatInfo kFormats[kFormatCount] = {
    {Format::R8, "R8", 1},           {Format::R16F, "R16F", 2},
    {Format::R32F, "R32F", 4},       {Format::RG16F, "RG16F", 4},
    {Format::RG32F, "RG32F", 8},     {Format::RGBA8, "RGBA8", 4},
    {Format::RGBA16F, "RGBA16F", 8}, {Format::RGBA32F, "RGBA32F", 16},
    {Format::DEPTH32F, "DEPTH32F", 4},
};

bool parse_int(std::string_view s, int& out) {
  if (s.empty()) return false;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc{} && p == s.data() + s.size();
}
}  // namespace

const char* format_name(Format format) { return kFormats[static_cast<int>(format)].name; }
int bytes_per_texel(Format format) { return kFormats[static_cast<int>(format)].bytes; }

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
