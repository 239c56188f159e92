#pragma once
// The texture formats the techniques need, and how each maps to GL and to bytes.
// The enum is shared with the GL-free graph compiler via graph/texture_format.h when present;
// here it carries the GL side of each format.
#include <glad/gl.h>

#include <optional>
#include <string_view>

namespace penumbra::gl {

enum class Format { R8, R16F, R32F, RG16F, RG32F, RGBA8, RGBA16F, RGBA32F, DEPTH32F };

struct FormatInfo {
  Format format;
  std::string_view name;   // as written in graph JSON
  GLenum internal_format;  // for glTextureStorage2D
  GLenum pixel_format;     // for read back / upload
  GLenum pixel_type;
  int channels;
  int bytes_per_texel;
  bool is_depth;
  bool image_compatible;  // usable with imageLoad/imageStore (depth formats are not)
};

const FormatInfo& format_info(Format f);
std::optional<Format> parse_format(std::string_view name);

}  // namespace penumbra::gl
