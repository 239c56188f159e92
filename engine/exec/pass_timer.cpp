#include "exec/pass_timer.h"

#include <algorithm>

namespace penumbra::exec {

double PassTiming::median_ms() const {
  if (history.empty()) return last_ms;
  std::vector<float> v(history.begin(), history.end());
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

void PassTimer::reset(const std::vector<std::string>& pass_names, TimingMode mode) {
  mode_ = mode;
  timings_.clear();
  for (const std::string& n : pass_names) timings_.push_back({n, 0.0, {}});
  for (GpuSlot& s : slots_) {
    s.begin.clear();
    s.end.clear();
    s.pending = false;
    if (mode_ != TimingMode::gpu_timestamps) continue;
    for (size_t i = 0; i < pass_names.size(); ++i) {
      s.begin.push_back(std::make_unique<gl::TimerQuery>());
      s.end.push_back(std::make_unique<gl::TimerQuery>());
    }
  }
}

void PassTimer::record(size_t index, double ms) {
  PassTiming& t = timings_[index];
  t.last_ms = ms;
  t.history.push_back(static_cast<float>(ms));
  if (t.history.size() > PassTiming::kHistory) t.history.pop_front();
}

void PassTimer::begin_frame(std::uint32_t frame) {
  frame_ = frame;
  if (mode_ != TimingMode::gpu_timestamps) return;
  // Collect the frame that last used this slot, if the GPU has finished it; never wait.
  GpuSlot& s = slots_[frame_ % kFrames];
  if (!s.pending) return;
  if (s.end.empty() || !s.end.back()->available()) {
    s.pending = false;  // drop this sample rather than stall
    return;
  }
  for (size_t i = 0; i < s.begin.size(); ++i)
    record(i, static_cast<double>(s.end[i]->result_ns() - s.begin[i]->result_ns()) * 1e-6);
  s.pending = false;
}

void PassTimer::begin_pass(size_t index) {
  if (mode_ == TimingMode::gpu_timestamps) {
    slots_[frame_ % kFrames].begin[index]->timestamp();
  } else if (mode_ == TimingMode::cpu_finish) {
    glFinish();
    cpu_start_ = std::chrono::steady_clock::now();
  }
}

void PassTimer::end_pass(size_t index) {
  if (mode_ == TimingMode::gpu_timestamps) {
    slots_[frame_ % kFrames].end[index]->timestamp();
  } else if (mode_ == TimingMode::cpu_finish) {
    glFinish();
    auto dt = std::chrono::steady_clock::now() - cpu_start_;
    record(index, std::chrono::duration<double, std::milli>(dt).count());
  }
}

void PassTimer::end_frame() {
  if (mode_ == TimingMode::gpu_timestamps) slots_[frame_ % kFrames].pending = true;
}

double PassTimer::total_last_ms() const {
  double total = 0.0;
  for (const PassTiming& t : timings_) total += t.last_ms;
  return total;
}

}  // namespace penumbra::exec
