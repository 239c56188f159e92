#pragma once
// Frame sequences: N frames along a camera orbit or a turning light, saved as numbered images
// (flicker review, figures). The poses are GL-free (unit-tested); the controller renders and
// saves one frame of the sequence per render_frame().
//
//   {"record": {"frames": 24, "path": "orbit", "degrees": 360, "dir": "seq"}}
//   -> seq/frame_0000.png .. seq/frame_0023.png, frame i at degrees * i / frames
#include <string>

#include "scene/camera.h"
#include "scene/light.h"
#include "util/error.h"

namespace penumbra::sandbox {

struct SequenceSpec {
  enum class Path { orbit, light };  // the camera about the scene centre, or the light
  Path path = Path::orbit;
  int frames = 24;          // 1..10000
  float degrees = 360.0f;   // total turn about the vertical axis, -3600..3600
  std::string dir;          // an existing folder
};
inline constexpr int kMaxSequenceFrames = 10000;

// "orbit" | "light"; an error naming both otherwise.
Result<SequenceSpec::Path> parse_sequence_path(const std::string& name);
// The frame count, turn and folder checked: an error says which is wrong.
Status check_sequence(const SequenceSpec& spec);

// The camera turned by `degrees` about the vertical axis through `centre` (position and view
// direction alike: the scene turns in front of it).
scene::Camera orbited(scene::Camera camera, const glm::vec3& centre, float degrees);
// The light turned likewise (direction, and position about `centre`).
scene::Light turned(scene::Light light, const glm::vec3& centre, float degrees);
// The file of frame `index`: DIR/frame_0007.png.
std::string sequence_frame_path(const SequenceSpec& spec, int index);

}  // namespace penumbra::sandbox
