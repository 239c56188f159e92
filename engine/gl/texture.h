#pragma once
// A 2D texture with immutable storage (glTextureStorage2D), created through DSA.
//
//   gl::Texture mask(gl::Format::R16F, 512, 512);
//   mask.clear(1.0f);                         // lit
//   std::vector<float> texels = mask.read();  // channels() floats per texel, row 0 at the bottom
#include <vector>

#include "gl/gl_handle.h"
#include "gl/texture_format.h"

namespace penumbra::gl {

class Texture {
 public:
  Texture() = default;
  Texture(Format format, int width, int height, int levels = 1);

  GLuint id() const { return handle_.id(); }
  explicit operator bool() const { return static_cast<bool>(handle_); }
  Format format() const { return format_; }
  const FormatInfo& info() const { return format_info(format_); }
  int width() const { return width_; }
  int height() const { return height_; }
  int levels() const { return levels_; }
  size_t bytes() const { return static_cast<size_t>(width_) * height_ * info().bytes_per_texel; }

  void set_filter(GLenum min_filter, GLenum mag_filter);
  void set_wrap(GLenum wrap);
  void set_label(const char* label);

  // Fills every channel of level 0 with `value` (depth formats: the depth value).
  void clear(float value);
  // Upload level 0 from `channels()` floats per texel (or bytes for 8-bit formats).
  void upload(const float* texels);
  void upload_bytes(const unsigned char* texels);

  // Level 0 as floats, info().channels per texel, rows bottom to top (GL order).
  std::vector<float> read() const;

 private:
  GlHandle<delete_texture> handle_;
  Format format_ = Format::RGBA8;
  int width_ = 0, height_ = 0, levels_ = 0;
};

// Sampler state kept apart from the texture, so one depth texture can be read both as depth
// (sampler2D) and with hardware comparison (sampler2DShadow) by different passes.
class Sampler {
 public:
  enum class Filter { nearest, linear };
  enum class Wrap { clamp, repeat };
  Sampler() = default;
  Sampler(Filter filter, Wrap wrap, bool depth_compare = false);
  GLuint id() const { return handle_.id(); }

 private:
  GlHandle<delete_sampler> handle_;
};

}  // namespace penumbra::gl
