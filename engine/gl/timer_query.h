#pragma once
// One GL_TIMESTAMP query. exec::PassTimer brackets every pass with two of them and reads the
// results frames later, once available() says so, so timing does not stall the GPU.
#include "gl/gl_handle.h"

namespace penumbra::gl {

class TimerQuery {
 public:
  TimerQuery();
  GLuint id() const { return handle_.id(); }
  void timestamp() const { glQueryCounter(id(), GL_TIMESTAMP); }
  bool available() const;
  // Nanoseconds; only meaningful once available().
  GLuint64 result_ns() const;

 private:
  GlHandle<delete_query> handle_;
};

}  // namespace penumbra::gl
