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

std::optional<double> GpuSpanTimer::collect(int frame) {
  // The slot about to be reused next frame holds the oldest measurement.
  int slot = (frame + 1) % kFramesInFlight;
  if (!pending_[slot]) return std::nullopt;
  Slot& s = slots_[slot];
  if (!s.end.available() || !s.begin.available()) return std::nullopt;
  pending_[slot] = false;
  return static_cast<double>(s.end.result_ns() - s.begin.result_ns()) * 1e-6;
}

}  // namespace penumbra::gl
