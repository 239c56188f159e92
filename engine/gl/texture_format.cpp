#include "gl/texture_format.h"

#include <array>

namespace penumbra::gl {

static constexpr std::array<FormatInfo, 9> kFormats = {{
    {Format::R8, "R8", GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1, 1, false, true},
    {Format::R16F, "R16F", GL_R16F, GL_RED, GL_FLOAT, 1, 2, false, true},
    {Format::R32F, "R32F", GL_R32F, GL_RED, GL_FLOAT, 1, 4, false, true},
    {Format::RG16F, "RG16F", GL_RG16F, GL_RG, GL_FLOAT, 2, 4, false, true},
    {Format::RG32F, "RG32F", GL_RG32F, GL_RG, GL_FLOAT, 2, 8, false, true},
    {Format::RGBA8, "RGBA8", GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, 4, false, true},
    {Format::RGBA16F, "RGBA16F", GL_RGBA16F, GL_RGBA, GL_FLOAT, 4, 8, false, true},
    {Format::RGBA32F, "RGBA32F", GL_RGBA32F, GL_RGBA, GL_FLOAT, 4, 16, false, true},
    {Format::DEPTH32F, "DEPTH32F", GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, 1, 4, true,
     false},
}};

const FormatInfo& format_info(Format f) { return kFormats[static_cast<size_t>(f)]; }

std::optional<Format> parse_format(std::string_view name) {
  for (const FormatInfo& info : kFormats)
    if (info.name == name) return info.format;
  return std::nullopt;
}

}  // namespace penumbra::gl
