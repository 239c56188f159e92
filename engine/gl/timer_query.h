#pragma once
// GPU timestamps that never stall: each frame writes into its own ring slot and results are
// read FRAMES_IN_FLIGHT frames later, only once GL_QUERY_RESULT_AVAILABLE says so.
#include <array>
#include <optional>

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

// Times one span of GPU work per frame, reporting the span of an earlier frame.
class GpuSpanTimer {
 public:
  static constexpr int kFramesInFlight = 4;
  void begin(int frame) { slots_[frame % kFramesInFlight].begin.timestamp(); pending_[frame % kFramesInFlight] = true; }
  void end(int frame) { slots_[frame % kFramesInFlight].end.timestamp(); }
  // Milliseconds of the oldest pending frame if its queries are ready; never waits.
  std::optional<double> collect(int frame);

 private:
  struct Slot {
    TimerQuery begin, end;
  };
  std::array<Slot, kFramesInFlight> slots_;
  std::array<bool, kFramesInFlight> pending_{};
};

}  // namespace penumbra::gl
