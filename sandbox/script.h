#pragma once
// Sandbox scripts: a JSON list of steps run through the same controller calls as the UI.
// GL-free: parsing, validation and the generated test scripts are unit-tested without a window.
//
//   [{"scene": "ball"}, {"technique": "pcss"}, {"set": {"samples": 32}},
//    {"camera": {"position": [0, 2, 6], "yaw": 0, "pitch": -15}},
//    {"light": {"direction": [-1, -2, -1], "size": 0.3}}, {"wait": 3},
//    {"compare": true}, {"screenshot": "out.png"}, {"expect_no_gl_error": true}]
//
// Each step is an object with exactly one key; see docs/sandbox.md for every step. Errors name
// the step index (0-based, as in the JSON array) and what was expected.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "graph/parameters.h"
#include "sandbox/frame_sequence.h"
#include "util/error.h"

namespace penumbra::sandbox {

enum class StepKind {
  scene, technique, set, reset, camera, light, shadow_size, wait, screenshot, compare, view,
  resize, expect_no_gl_error, ground, metrics, inspect, graph, debug, save_view, record
};
const char* step_kind_name(StepKind kind);

struct CameraStep {
  // {"camera": "fit"} / {"camera": "file"} / {"camera": "file:NAME"}: restage the scene with the
  // fitted camera or one the glTF places (the other fields are then unset).
  std::optional<std::string> choice;
  std::optional<glm::vec3> position;
  std::optional<glm::vec3> look_at;  // world point; overrides yaw/pitch
  std::optional<float> yaw_deg, pitch_deg;
};

struct LightStep {
  std::optional<std::string> type;  // "directional" | "spot" | "point"
  std::optional<glm::vec3> direction, position;
  std::optional<float> size;          // emitter disk diameter, world units
  std::optional<float> spot_angle_deg;  // cone half-angle, degrees
  std::optional<bool> frozen;           // freeze the light (refuse changes) / unfreeze
};

struct CompareStep {
  bool enabled = false;
  std::string with;  // technique to compare against; empty = "reference" if registered, else the next one
  std::string view;  // "split" | "error"; empty = unchanged
  std::optional<bool> three_way;  // A | B | reference
  std::optional<bool> classes;    // the error view shows the pixel classes instead of the error
};

struct ViewStep {
  std::string resource;  // empty = viewer off
  std::string map;       // "color" | "grey" | "heat"; empty = unchanged
  std::string placement; // "full" | "inset"; empty = unchanged
  std::optional<float> min, max;
  std::optional<int> channel;
  std::optional<unsigned> channel_mask;  // "channels": "rgb", "a", ... (colour map)
  std::optional<float> zoom;           // 1..64
  std::optional<glm::vec2> center;     // uv at the frame's middle
  std::optional<bool> auto_range;
};

// {"inspect": {"at": [x, y], "out": "p.json"}}: the pixel inspector's readout of frame pixel
// (x, y) (origin top-left) written as JSON.
struct InspectStep {
  int x = 0, y = 0;
  std::string out;
};

struct ScriptStep {
  StepKind kind = StepKind::wait;
  int index = 0;     // position in the script
  std::string source;  // the script file, named by errors
  std::string text;  // scene, technique, screenshot or metrics path, reset target ("all" or a parameter),
                     // save_view's folder
  std::string format;  // save_view: "png" | "pfm"
  std::vector<std::pair<std::string, std::string>> assignments;  // set: name -> value text
  int number = 0;    // wait frames, shadow size (texels)
  bool flag = false;  // ground: the switch
  std::optional<bool> light_frustum, blocker_region, texel_density, light_gizmo;  // debug: debug views
  int width = 0, height = 0;  // resize (pixels)
  CameraStep camera;
  LightStep light;
  CompareStep compare;
  ViewStep view;
  InspectStep inspect;
  SequenceSpec sequence;  // record
};

// Limits of a script (docs/sandbox.md): steps; nesting is util/json_text.h's kMaxJsonDepth.
inline constexpr size_t kMaxScriptSteps = 100000;

// `source` names the file in errors.
Result<std::vector<ScriptStep>> parse_script(const std::string& text, const std::string& source);

// An error raised while running step `step` (the runner's errors use the same words as parse
// errors, so a user finds the step either way).
Error step_error(const ScriptStep& step, const std::string& message);

// What the generators need to know about one technique.
struct TechniqueInfo {
  std::string name;
  std::vector<graph::ParamDesc> params;
};

// Swaps through every technique; sets every parameter to its min, max and default (booleans
// false/true, enumerations every option), renders, toggles compare mode and takes screenshots
// into `screenshot_dir` (named <technique>.png and <technique>_compare.png), asserting no GL
// error after each technique.
std::string exhaustive_script(const std::vector<TechniqueInfo>& techniques,
                              const std::string& screenshot_dir, int width, int height,
                              int shadow_size);

// `steps` random steps (technique swaps, parameter changes, resizes, compare toggles against
// techniques of the list, resets, waits), reproducible from `seed`; ends with
// {"expect_no_gl_error": true}.
std::string soak_script(const std::vector<TechniqueInfo>& techniques, std::uint32_t seed, int steps,
                        int max_size);

}  // namespace penumbra::sandbox
