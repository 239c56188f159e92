#pragma once
// Writes a texture to PNG: colour formats as colour (clamped to [0,1]), single-channel formats
// as grey over [0,1], depth normalised over the finite range actually present (so a depth map
// is visible whatever its near/far), flipped so the PNG's first row is the image top.
#include <string>

#include "gl/texture.h"
#include "util/error.h"

namespace penumbra::gl {

Status write_texture_png(const Texture& texture, const std::string& path);

}  // namespace penumbra::gl
