#include "sandbox/input_queue.h"

#include <algorithm>

namespace penumbra::sandbox {

std::vector<InputEvent> InputQueue::take_frame() {
  std::vector<InputEvent> out;
  std::vector<int> pressed, released;  // keys pressed / released in this frame's events
  auto in = [](const std::vector<int>& keys, int key) { return std::find(keys.begin(), keys.end(), key) != keys.end(); };
  while (!pending_.empty()) {
    const InputEvent& e = pending_.front();
    if (e.kind == InputEvent::Kind::key) {
      if (e.action == InputEvent::kRelease && in(pressed, e.key)) break;  // keep the tap down for this frame
      // A new press of a key released this frame would leave it down at both samples, its
      // press unseen (two BackSpaces deleted one character): it waits for the next frame.
      if (e.action == InputEvent::kPress && in(released, e.key)) break;
      if (e.action == InputEvent::kPress) pressed.push_back(e.key);
      if (e.action == InputEvent::kRelease) released.push_back(e.key);
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
