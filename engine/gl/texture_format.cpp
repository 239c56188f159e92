#include "gl/texture_format.h"

#include <array>

namespace penumbra::gl {

namespace {

struct GlEnums {
  Format format;
  GLenum internal_format, pixel_format;
};
constexpr std::array<GlEnums, graph::kFormatCount> kGl = {{
    {Format::R8, GL_R8, GL_RED},
    {Format::R16F, GL_R16F, GL_RED},
    {Format::R32F, GL_R32F, GL_RED},
    {Format::RG16F, GL_RG16F, GL_RG},
    {Format::RG32F, GL_RG32F, GL_RG},
    {Format::RGBA8, GL_RGBA8, GL_RGBA},
    {Format::RGBA16F, GL_RGBA16F, GL_RGBA},
    {Format::RGBA32F, GL_RGBA32F, GL_RGBA},
    {Format::DEPTH32F, GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT},
    {Format::R16, GL_R16, GL_RED},
    {Format::RG16, GL_RG16, GL_RG},
    {Format::R16_SNORM, GL_R16_SNORM, GL_RED},
    {Format::RG16_SNORM, GL_RG16_SNORM, GL_RG},
    {Format::RGB10A2, GL_RGB10_A2, GL_RGBA},
    {Format::R11G11B10F, GL_R11F_G11F_B10F, GL_RGB},
    {Format::RGBA16, GL_RGBA16, GL_RGBA},
    {Format::RGBA16_SNORM, GL_RGBA16_SNORM, GL_RGBA},
}};

constexpr bool listed_in_enum_order() {
  for (size_t i = 0; i < kGl.size(); ++i)
    if (static_cast<size_t>(kGl[i].format) != i) return false;
  return true;
}
static_assert(listed_in_enum_order(), "kGl is indexed by Format");

std::array<FormatInfo, graph::kFormatCount> make_infos() {
  std::array<FormatInfo, graph::kFormatCount> out{};
  for (size_t i = 0; i < kGl.size(); ++i) {
    const Format f = kGl[i].format;
    out[i] = {f,
              graph::format_name(f),
              kGl[i].internal_format,
              kGl[i].pixel_format,
              graph::channel_count(f),
              graph::bytes_per_texel(f),
              graph::is_depth_format(f),
              !graph::is_depth_format(f)};
  }
  return out;
}

}  // namespace

const FormatInfo& format_info(Format f) {
  static const std::array<FormatInfo, graph::kFormatCount> infos = make_infos();
  return infos[static_cast<size_t>(f)];
}

}  // namespace penumbra::gl
