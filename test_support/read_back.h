#pragma once
// GL textures read back into CPU images, in ONE row order: rows top to bottom (row 0 is the top
// of the picture, as in PNG files, metrics::MaskImage and the ray-traced reference), the reverse
// of GL's bottom-up order (gl::Texture::read()). Pixel (x, y) of a TextureImage is at
// texels[(y * width + x) * channels + c]; upload_pass.h takes its texels in the same order.
#include <vector>

#include "gl/texture.h"
#include "metrics/mask_image.h"

namespace penumbra::test {

struct TextureImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> texels;  // width * height * channels, rows top to bottom

  float at(int x, int y, int c = 0) const { return texels[(static_cast<size_t>(y) * width + x) * channels + c]; }
  float& at(int x, int y, int c = 0) { return texels[(static_cast<size_t>(y) * width + x) * channels + c]; }
};

// Every channel of level 0 as floats (8-bit formats in [0, 1]).
TextureImage read_texture(const gl::Texture& texture);
// One channel; a channel past the texture's last reads its last (a depth or R16F texture read as
// channel 3 is its only channel).
metrics::MaskImage read_channel(const gl::Texture& texture, int channel = 0);
// A 4-channel texture as 8-bit RGBA ([0, 1] -> 0..255, clamped); empty for other textures.
metrics::RgbaImage read_rgba8(const gl::Texture& texture);
// GL's bottom-up rows <-> top-down rows (the same swap both ways).
std::vector<float> flip_rows(const std::vector<float>& texels, int width, int height, int channels);

}  // namespace penumbra::test
