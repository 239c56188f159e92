#include "gl/timer_query.h"

namespace penumbra::gl {

TimerQuery::TimerQuery() {
  GLuint id = 0;
  glCreateQueries(GL_TIMESTAMP, 1, &id);
  handle_ = GlHandle<delete_query>(id);
}

bool TimerQuery::available() const {
  GLint ready = 0;
  glGetQueryObjectiv(id(), GL_QUERY_RESULT_AVAILABLE, &ready);
  return ready != 0;
}

GLuint64 TimerQuery::result_ns() const {
  GLuint64 ns = 0;
  glGetQueryObjectui64v(id(), GL_QUERY_RESULT, &ns);
  return ns;
}

}  // namespace penumbra::gl
