#include "sandbox/input_queue.h"

#include <algorithm>

namespace penumbra::sandbox {

std::vector<InputEvent> InputQueue::take_frame() {
  std::vector<InputEvent> out;
  std::vector<int> pressed;  // keys pressed in this frame's events
  while (!pending_.empty()) {
    const InputEvent& e = pending_.front();
    if (e.kind == InputEvent::Kind::key) {
      const bool was_pressed = std::find(pressed.begin(), pressed.end(), e.key) != pressed.end();
      if (e.action == InputEvent::kRelease && was_pressed) break;  // keep the tap down for this frame
      if (e.action == InputEvent::kPress) pressed.push_back(e.key);
    }
    out.push_back(e);
    pending_.pop_front();
  }
  return out;
}

bool pressed_in(const std::vector<InputEvent>& events, int key) {
  return std::any_of(events.begin(), events.end(), [&](const InputEvent& e) {
    return e.kind == InputEvent::Kind::key && e.key == key && e.action == InputEvent::kPress;
  });
}

}  // namespace penumbra::sandbox
