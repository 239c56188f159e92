#include "gl/texture.h"

namespace penumbra::gl {

Texture::Texture(Format format, int width, int height, int levels)
    : format_(format), width_(width), height_(height), levels_(levels) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  handle_ = GlHandle<delete_texture>(id);
  glTextureStorage2D(id, levels, info().internal_format, width, height);
  // Nearest by default: most passes fetch exact texels; bilinear is asked for explicitly.
  set_filter(GL_NEAREST, GL_NEAREST);
  set_wrap(GL_CLAMP_TO_EDGE);
}

void Texture::set_filter(GLenum min_filter, GLenum mag_filter) {
  glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, min_filter);
  glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, mag_filter);
}

void Texture::set_wrap(GLenum wrap) {
  glTextureParameteri(id(), GL_TEXTURE_WRAP_S, wrap);
  glTextureParameteri(id(), GL_TEXTURE_WRAP_T, wrap);
}

void Texture::set_label(const char* label) { glObjectLabel(GL_TEXTURE, id(), -1, label); }

void Texture::clear(float value) {
  const FormatInfo& f = info();
  if (f.is_depth) {
    glClearTexImage(id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &value);
    return;
  }
  const float v[4] = {value, value, value, value};
  glClearTexImage(id(), 0, f.pixel_format, GL_FLOAT, v);
}

void Texture::upload(const float* texels) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(id(), 0, 0, 0, width_, height_, info().pixel_format, GL_FLOAT, texels);
}

void Texture::upload_bytes(const unsigned char* texels) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(id(), 0, 0, 0, width_, height_, info().pixel_format, GL_UNSIGNED_BYTE,
                      texels);
}

std::vector<float> Texture::read() const {
  const FormatInfo& f = info();
  std::vector<float> out(static_cast<size_t>(width_) * height_ * f.channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(id(), 0, f.pixel_format, GL_FLOAT, static_cast<GLsizei>(out.size() * sizeof(float)),
                    out.data());
  return out;
}

Sampler::Sampler(Filter filter, Wrap wrap, bool depth_compare) {
  GLuint id = 0;
  glCreateSamplers(1, &id);
  handle_ = GlHandle<delete_sampler>(id);
  GLenum f = filter == Filter::linear ? GL_LINEAR : GL_NEAREST;
  GLenum w = wrap == Wrap::repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, f);
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, f);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_S, w);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_T, w);
  if (depth_compare) {
    glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(id, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  }
}

}  // namespace penumbra::gl
