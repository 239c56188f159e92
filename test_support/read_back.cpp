#include "test_support/read_back.h"

#include "util/row_order.h"

#include <algorithm>
#include <cmath>

namespace penumbra::test {

std::vector<float> flip_rows(const std::vector<float>& texels, int width, int height, int channels) {
  return rows_flipped(texels, static_cast<size_t>(width) * static_cast<size_t>(channels), height);
}

TextureImage read_texture(const gl::Texture& texture) {
  TextureImage image{texture.width(), texture.height(), texture.info().channels, {}};
  image.texels = flip_rows(texture.read(), image.width, image.height, image.channels);
  return image;
}

metrics::MaskImage read_channel(const gl::Texture& texture, int channel) {
  const TextureImage image = read_texture(texture);
  channel = std::clamp(channel, 0, image.channels - 1);
  metrics::MaskImage m(image.width, image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) m.at(x, y) = image.at(x, y, channel);
  return m;
}

metrics::RgbaImage read_rgba8(const gl::Texture& texture) {
  metrics::RgbaImage out;
  if (texture.info().channels != 4) return out;
  const TextureImage image = read_texture(texture);
  out.width = image.width;
  out.height = image.height;
  out.pixels.resize(image.texels.size());
  for (size_t i = 0; i < image.texels.size(); ++i)
    out.pixels[i] = static_cast<uint8_t>(std::clamp(image.texels[i], 0.0f, 1.0f) * 255.0f + 0.5f);
  return out;
}

}  // namespace penumbra::test
