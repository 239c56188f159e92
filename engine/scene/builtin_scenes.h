#pragma once
// Procedural scenes that need no files, reproducing the papers' test scenes. World units are
// metres, Y up, ground at y = 0. Each has a default camera and a directional light whose emitter
// diameter is a few % of the scene width, so penumbrae are clearly visible.
//   fence      picket fence on a ground plane (Cherry & Kooima's Fence): thin shadow lines whose
//              penumbra grows away from the base.
//   ball       a sphere above a plane under a LOW light: elongated shadow; `ball_height`.
//   poles      thin poles of several heights and tilts standing on / floating over the ground.
//   colonnade  a Sponza-like court of columns and arches with poles hanging high above the floor
//              (Sterna 2018's views).
//   palms      palm trees whose fronds are alpha-masked quads (Cherry & Kooima's Pool scene) and a
//              low wall; `palm_height`, `frond_count`, `frond_length`.
//   room       a closed room lit by a lamp (a point light inside the scene) hanging from the
//              ceiling: table, ball, chair, cabinet and shelf; `lamp_height`, `light_size`.
//   showcase   (default) fence, ball, poles and colonnade on one ground.
//   avenue     a 200 m street under the sun: lamp posts along both sides, a pergola and benches
//              near the camera at eye height (casters from 1 m to 200 m: cascades); `length`.
//
//   Result<Scene> s = make_builtin_scene("ball", {{"ball_height", 1.5f}});
#include <map>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "util/error.h"

namespace penumbra::scene {

// One tunable dimension of a built-in scene.
struct ProceduralParam {
  std::string key;
  float default_value = 0.0f;
  std::string description;  // says the unit
};

// Overrides by key; keys not given take their defaults. Unknown keys are an error.
using ProceduralParams = std::map<std::string, float>;

std::vector<std::string> builtin_scene_names();
// The parameters of a scene (empty for an unknown name).
std::vector<ProceduralParam> builtin_scene_params(const std::string& name);
// Unknown name -> Error listing the valid names; unknown key -> Error listing the valid keys.
Result<Scene> make_builtin_scene(const std::string& name, const ProceduralParams& params = {});

}  // namespace penumbra::scene
