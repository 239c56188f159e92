#pragma once
// Per-pass timing. On a GPU: GL_TIMESTAMP queries around every pass; each frame's queries wait
// in a queue and are read once GL_QUERY_RESULT_AVAILABLE says so, a few frames later, so timing
// does not stall the pipeline. Only when the CPU runs more than kMaxPendingFrames ahead of the
// GPU is the oldest frame's result waited for (the driver would throttle such a loop at
// present time anyway); no measurement is ever dropped. flush() waits for all of them, for a
// benchmark's last frames. On llvmpipe timer
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
// How the times were taken, for labels: "GPU timestamps", "glFinish + CPU clock", "off".
const char* timing_mode_name(TimingMode mode);

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
  // Drops the frame being recorded (a pass failed: some of its queries were never issued).
  void abort_frame();
  // Waits for every pending GPU measurement and records it (benchmarks, before reading).
  void flush();
  const std::vector<PassTiming>& timings() const { return timings_; }
  double total_last_ms() const;

 private:
  static constexpr size_t kMaxPendingFrames = 8;
  struct FrameQueries {
    std::vector<std::unique_ptr<gl::TimerQuery>> begin, end;
  };
  void record(size_t index, double ms);
  // Records finished frames, oldest first; with wait=true blocks until each is available.
  void collect(bool wait);
  FrameQueries take_query_set();
  TimingMode mode_ = TimingMode::off;
  std::vector<PassTiming> timings_;
  std::deque<FrameQueries> pending_;  // submitted, not yet read, oldest first
  std::vector<FrameQueries> spare_;   // read, reusable
  FrameQueries current_;
  bool in_frame_ = false;
  std::chrono::steady_clock::time_point cpu_start_;
};

}  // namespace penumbra::exec
