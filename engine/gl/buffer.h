#pragma once
// A GL buffer with immutable storage (glNamedBufferStorage). Dynamic buffers allow
// glNamedBufferSubData updates (uniform blocks updated per frame).
#include <span>
#include <vector>

#include "gl/gl_handle.h"

namespace penumbra::gl {

class Buffer {
 public:
  Buffer() = default;
  Buffer(size_t bytes, const void* data = nullptr, bool dynamic = true);
  template <class T>
  static Buffer from(std::span<const T> items, bool dynamic = false) {
    return Buffer(items.size_bytes(), items.data(), dynamic);
  }

  GLuint id() const { return handle_.id(); }
  size_t size() const { return size_; }
  void update(const void* data, size_t bytes, size_t offset = 0);
  void clear_zero();
  void bind_base(GLenum target, GLuint index) const { glBindBufferBase(target, index, id()); }
  std::vector<unsigned char> read(size_t bytes, size_t offset = 0) const;
  template <class T>
  std::vector<T> read_as() const {
    std::vector<T> out(size_ / sizeof(T));
    glGetNamedBufferSubData(id(), 0, out.size() * sizeof(T), out.data());
    return out;
  }

 private:
  GlHandle<delete_buffer> handle_;
  size_t size_ = 0;
};

}  // namespace penumbra::gl
