// The frame loop's key queue: a tap (press + release between two frames) is down for a frame.
#include <gtest/gtest.h>

#include "sandbox/input_queue.h"

namespace {

using penumbra::sandbox::InputEvent;
using penumbra::sandbox::InputQueue;

constexpr int kCtrl = 341, kA = 65, kSpace = 32;  // GLFW key codes

InputEvent key(int k, int action) { return {.kind = InputEvent::Kind::key, .key = k, .action = action}; }
InputEvent ch(unsigned c) { return {.kind = InputEvent::Kind::character, .codepoint = c}; }

TEST(InputQueue, CtrlATypedInOneFrameReachesTwoFramesWithAHeldInTheFirst) {
  InputQueue q;
  for (const InputEvent& e : {key(kCtrl, InputEvent::kPress), key(kA, InputEvent::kPress), key(kA, InputEvent::kRelease),
                              key(kCtrl, InputEvent::kRelease), ch('x')})
    q.push(e);
  const auto first = q.take_frame();
  ASSERT_EQ(first.size(), 2u);
  EXPECT_EQ(first[0].key, kCtrl);
  EXPECT_EQ(first[1].key, kA);
  EXPECT_EQ(first[1].action, InputEvent::kPress);
  const auto second = q.take_frame();
  ASSERT_EQ(second.size(), 3u);  // A up, Ctrl up, then the character: after the selection
  EXPECT_EQ(second[0].action, InputEvent::kRelease);
  EXPECT_EQ(second[2].kind, InputEvent::Kind::character);
  EXPECT_TRUE(q.empty());
  EXPECT_TRUE(q.take_frame().empty());
}

TEST(InputQueue, TwoTapsOfOneKeyTakeTwoFramesEach) {
  InputQueue q;
  for (int i = 0; i < 2; ++i) {
    q.push(key(kSpace, InputEvent::kPress));
    q.push(key(kSpace, InputEvent::kRelease));
  }
  int frames_with_a_press = 0, frames = 0;
  while (!q.empty() && frames < 10) {
    frames_with_a_press += penumbra::sandbox::pressed_in(q.take_frame(), kSpace) ? 1 : 0;
    ++frames;
  }
  EXPECT_EQ(frames_with_a_press, 2);
  // press | release | press | release: ImGui samples key state once a frame, so a release and a
  // new press in one frame would leave the key down at both samples and the second press unseen
  // (two BackSpaces in a row deleted one character).
  EXPECT_EQ(frames, 4);
}

TEST(InputQueue, CharactersAndHeldKeysPassInOneFrame) {
  InputQueue q;
  q.push(key(kA, InputEvent::kPress));
  q.push(ch('a'));
  q.push(ch('b'));
  q.push(key(kSpace, InputEvent::kRelease));  // released, but pressed in an earlier frame
  EXPECT_EQ(q.take_frame().size(), 4u);
  EXPECT_FALSE(penumbra::sandbox::pressed_in({key(kA, InputEvent::kRepeat)}, kA));
}

}  // namespace
