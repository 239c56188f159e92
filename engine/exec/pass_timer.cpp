#include "exec/pass_timer.h"

#include <algorithm>

namespace penumbra::exec {

double PassTiming::median_ms() const {
  if (history.empty()) return last_ms;
  std::vector<float> v(history.begin(), history.end());
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

const char* timing_mode_name(TimingMode mode) {
  switch (mode) {
    case TimingMode::gpu_timestamps: return "GPU timestamps";
    case TimingMode::cpu_finish: return "glFinish + CPU clock";
    case TimingMode::off: return "off";
  }
  return "?";
}

void PassTimer::reset(const std::vector<std::string>& pass_names, TimingMode mode) {
  mode_ = mode;
  timings_.clear();
  for (const std::string& n : pass_names) timings_.push_back({n, 0.0, {}});
  pending_.clear();
  spare_.clear();
  current_ = {};
  in_frame_ = false;
}

void PassTimer::record(size_t index, double ms) {
  PassTiming& t = timings_[index];
  t.last_ms = ms;
  t.history.push_back(static_cast<float>(ms));
  if (t.history.size() > PassTiming::kHistory) t.history.pop_front();
}

PassTimer::FrameQueries PassTimer::take_query_set() {
  if (!spare_.empty()) {
    FrameQueries f = std::move(spare_.back());
    spare_.pop_back();
    return f;
  }
  FrameQueries f;
  for (size_t i = 0; i < timings_.size(); ++i) {
    f.begin.push_back(std::make_unique<gl::TimerQuery>());
    f.end.push_back(std::make_unique<gl::TimerQuery>());
  }
  return f;
}

void PassTimer::collect(bool wait) {
  while (!pending_.empty()) {
    FrameQueries& f = pending_.front();
    // Queries complete in submission order: the frame's last end stamp covers all of them.
    if (!wait && !f.end.empty() && !f.end.back()->available()) break;
    for (size_t i = 0; i < f.begin.size(); ++i)
      record(i, static_cast<double>(f.end[i]->result_ns() - f.begin[i]->result_ns()) * 1e-6);
    spare_.push_back(std::move(f));
    pending_.pop_front();
  }
}

void PassTimer::begin_frame(std::uint32_t frame) {
  if (mode_ != TimingMode::gpu_timestamps) return;
  collect(false);
  while (pending_.size() >= kMaxPendingFrames) {
    FrameQueries& oldest = pending_.front();
    (void)oldest.end.back()->result_ns();  // waits for the GPU to reach it
    collect(false);
  }
  current_ = take_query_set();
  in_frame_ = true;
}

void PassTimer::begin_pass(size_t index) {
  if (mode_ == TimingMode::gpu_timestamps) {
    current_.begin[index]->timestamp();
  } else if (mode_ == TimingMode::cpu_finish) {
    glFinish();
    cpu_start_ = std::chrono::steady_clock::now();
  }
}

void PassTimer::end_pass(size_t index) {
  if (mode_ == TimingMode::gpu_timestamps) {
    current_.end[index]->timestamp();
  } else if (mode_ == TimingMode::cpu_finish) {
    glFinish();
    auto dt = std::chrono::steady_clock::now() - cpu_start_;
    record(index, std::chrono::duration<double, std::milli>(dt).count());
  }
}

void PassTimer::end_frame() {
  if (mode_ != TimingMode::gpu_timestamps || !in_frame_) return;
  pending_.push_back(std::move(current_));
  current_ = {};
  in_frame_ = false;
}

void PassTimer::abort_frame() {
  if (!in_frame_) return;
  spare_.push_back(std::move(current_));
  current_ = {};
  in_frame_ = false;
}

void PassTimer::flush() {
  if (mode_ == TimingMode::gpu_timestamps) collect(true);
}

double PassTimer::total_last_ms() const {
  double total = 0.0;
  for (const PassTiming& t : timings_) total += t.last_ms;
  return total;
}

}  // namespace penumbra::exec
