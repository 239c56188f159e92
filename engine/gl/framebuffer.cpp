#include "gl/framebuffer.h"

#include <algorithm>
#include <string>

namespace penumbra::gl {

Framebuffer::Framebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  handle_ = GlHandle<delete_framebuffer>(id);
}

void Framebuffer::attach_color(int index, const Texture& texture, int level) {
  glNamedFramebufferTexture(id(), GL_COLOR_ATTACHMENT0 + index, texture.id(), level);
  GLenum a = GL_COLOR_ATTACHMENT0 + index;
  if (std::find(draw_buffers_.begin(), draw_buffers_.end(), a) == draw_buffers_.end())
    draw_buffers_.push_back(a);
  width_ = texture.width() >> level;
  height_ = texture.height() >> level;
}

void Framebuffer::attach_depth(const Texture& texture, int level) {
  glNamedFramebufferTexture(id(), GL_DEPTH_ATTACHMENT, texture.id(), level);
  width_ = texture.width() >> level;
  height_ = texture.height() >> level;
}

Status Framebuffer::finish() const {
  if (draw_buffers_.empty()) {
    glNamedFramebufferDrawBuffer(id(), GL_NONE);
  } else {
    std::vector<GLenum> sorted = draw_buffers_;
    std::sort(sorted.begin(), sorted.end());
    glNamedFramebufferDrawBuffers(id(), static_cast<GLsizei>(sorted.size()), sorted.data());
  }
  GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return make_error("framebuffer incomplete (status 0x" + [&] {
      char buf[16];
      snprintf(buf, sizeof buf, "%04X", status);
      return std::string(buf);
    }() + ")", ErrorKind::internal);
  }
  return {};
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, id());
  glViewport(0, 0, width_, height_);
}

}  // namespace penumbra::gl
