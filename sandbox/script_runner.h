#pragma once
// Runs a parsed script against the controller, frame by frame: before each frame the host calls
// before_frame(), which runs steps until one needs rendered frames ({"wait": N} renders N frames,
// {"screenshot": ...} renders one and asks the host to save it after composing).
//
//   ScriptRunner runner(std::move(steps), [&](int w, int h) { return host_resize(w, h); });
//   while (!runner.done()) {
//     if (Status s = runner.before_frame(controller); !s) return fail(s);   // names the step
//     controller.render_frame();
//     if (auto path = runner.take_screenshot()) save(*path);
//   }
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sandbox/controller.h"
#include "sandbox/script.h"

namespace penumbra::sandbox {

class ScriptRunner {
 public:
  using ResizeFn = std::function<Status(int, int)>;
  ScriptRunner(std::vector<ScriptStep> steps, ResizeFn resize);

  Status before_frame(SandboxController& controller);
  // True once every step ran and the last requested frame was rendered.
  bool done() const { return next_ >= steps_.size() && frames_left_ == 0 && !screenshot_; }
  // The screenshot the current frame must be saved to, if any (cleared by this call).
  std::optional<std::string> take_screenshot() { return std::exchange(screenshot_, std::nullopt); }
  // The step that ran last (for error messages of the frame that followed it).
  const ScriptStep* current() const { return last_ < steps_.size() ? &steps_[last_] : nullptr; }

 private:
  Status run(const ScriptStep& step, SandboxController& c);

  std::vector<ScriptStep> steps_;
  ResizeFn resize_;
  size_t next_ = 0;
  size_t last_ = static_cast<size_t>(-1);
  int frames_left_ = 0;
  std::optional<std::string> screenshot_;
};

// A pass may refuse a frame as bad input (a parameter combination it cannot run, e.g. a filter
// smaller than one texel of the shadow map). The UI shows that message and keeps running; a script
// does the same, printing a warning that names the step. Internal errors stop the script (exit 1).
bool frame_refusal_is_fatal(const Error& e);
void report_refused_frame(const Error& e);

// Runs the whole script with no window: frames are rendered into the controller's presentation
// texture and screenshots read from it (OSMesa/EGL runs, soak tests). `on_frame` (optional) is
// called after every frame, e.g. to check invariants.
Status run_script_headless(SandboxController& controller, ScriptRunner& runner,
                           const std::function<Status()>& on_frame = {});

}  // namespace penumbra::sandbox
