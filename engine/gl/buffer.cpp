#include "gl/buffer.h"

namespace penumbra::gl {

Buffer::Buffer(size_t bytes, const void* data, bool dynamic) : size_(bytes) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  handle_ = GlHandle<delete_buffer>(id);
  GLbitfield flags = dynamic ? GL_DYNAMIC_STORAGE_BIT : 0;
  glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes == 0 ? 4 : bytes), data, flags);
}

void Buffer::update(const void* data, size_t bytes, size_t offset) {
  glNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::clear_zero() {
  const unsigned int zero = 0;
  glClearNamedBufferData(id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

std::vector<unsigned char> Buffer::read(size_t bytes, size_t offset) const {
  std::vector<unsigned char> out(bytes);
  glGetNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes),
                          out.data());
  return out;
}

}  // namespace penumbra::gl
