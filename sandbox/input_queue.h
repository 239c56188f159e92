#pragma once
// Key and character events between the window system's callbacks and the frame loop
// (GL-free, unit-tested). Dear ImGui 1.86 samples key state once per frame, so a key pressed
// and released between two frames (a tap at a low frame rate, or Ctrl+A typed quickly) was
// never seen down. The queue hands each frame the events up to the release of a key pressed in
// that same frame; the release and everything after it wait for the next frame, and so does a
// new press of a key released in the frame (else it would look held, not pressed). Characters
// stay in order with the keys, so "Ctrl+A, then type" replaces the selection.
#include <deque>
#include <vector>

namespace penumbra::sandbox {

struct InputEvent {
  enum class Kind { key, character };
  // The action values are GLFW's (window_host.cpp checks them against glfw3.h).
  static constexpr int kRelease = 0, kPress = 1, kRepeat = 2;
  Kind kind = Kind::key;
  int key = 0, scancode = 0, action = 0, mods = 0;  // Kind::key
  unsigned codepoint = 0;                           // Kind::character
};

class InputQueue {
 public:
  void push(const InputEvent& e) { pending_.push_back(e); }
  // The events to deliver this frame (see above); never splits a frame's events otherwise.
  std::vector<InputEvent> take_frame();
  bool empty() const { return pending_.empty(); }

 private:
  std::deque<InputEvent> pending_;
};

// Whether `events` press `key` (a press, not a repeat).
bool pressed_in(const std::vector<InputEvent>& events, int key);

}  // namespace penumbra::sandbox
