#pragma once
// The GL side of the graph's texture formats (graph/resources.h holds the one list, with names,
// sizes and channels): the enums each format is created, uploaded and read back with.
#include <glad/gl.h>

#include <string_view>

#include "graph/resources.h"

namespace penumbra::gl {

using Format = graph::Format;

struct FormatInfo {
  Format format;
  std::string_view name;   // as written in graph JSON
  GLenum internal_format;  // for glTextureStorage2D and glBindImageTexture
  GLenum pixel_format;     // for read back / upload
  int channels;
  int bytes_per_texel;
  bool is_depth;
  bool image_compatible;  // usable with imageLoad/imageStore (depth formats are not)
};

const FormatInfo& format_info(Format f);

}  // namespace penumbra::gl
