#pragma once
// A framebuffer over existing textures (attachments are borrowed, not owned), for raster passes.
#include <vector>

#include "gl/gl_handle.h"
#include "gl/texture.h"
#include "util/error.h"

namespace penumbra::gl {

class Framebuffer {
 public:
  Framebuffer();
  GLuint id() const { return handle_.id(); }
  void attach_color(int index, const Texture& texture, int level = 0);
  void attach_depth(const Texture& texture, int level = 0);
  // Selects the attached colour buffers as draw buffers and checks completeness.
  Status finish() const;
  // Binds for drawing and sets the viewport to the attachments' size.
  void bind() const;

 private:
  GlHandle<delete_framebuffer> handle_;
  std::vector<GLenum> draw_buffers_;
  int width_ = 0, height_ = 0;
};

}  // namespace penumbra::gl
