#pragma once
// Per-pass timing. On a GPU: GL_TIMESTAMP queries around every pass, read kFramesInFlight
// frames later and only when available, so timing never stalls the pipeline. On llvmpipe timer
// queries do not measure the work (they return 0.1-0.8 ms for a 90 ms pass), so there the
// executor brackets each pass with glFinish and a CPU clock instead; the table is the same.
#include <chrono>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "gl/timer_query.h"

namespace penumbra::exec {

enum class TimingMode { gpu_timestamps, cpu_finish, off };

struct PassTiming {
  std::string name;
  double last_ms = 0.0;          // latest measurement
  std::deque<float> history;     // newest last, at most kHistory entries
  static constexpr size_t kHistory = 240;
  double median_ms() const;      // of the history
};

class PassTimer {
 public:
  void reset(const std::vector<std::string>& pass_names, TimingMode mode);
  TimingMode mode() const { return mode_; }
  void begin_frame(std::uint32_t frame);
  void begin_pass(size_t index);
  void end_pass(size_t index);
  void end_frame();
  const std::vector<PassTiming>& timings() const { return timings_; }
  double total_last_ms() const;

 private:
  static constexpr int kFrames = gl::GpuSpanTimer::kFramesInFlight;
  struct GpuSlot {
    std::vector<std::unique_ptr<gl::TimerQuery>> begin, end;
    bool pending = false;
  };
  void record(size_t index, double ms);
  TimingMode mode_ = TimingMode::off;
  std::vector<PassTiming> timings_;
  GpuSlot slots_[kFrames];
  std::uint32_t frame_ = 0;
  std::chrono::steady_clock::time_point cpu_start_;
};

}  // namespace penumbra::exec
