#pragma once
// Staging a loaded scene for a frame: the ground plane under a model that has none, the camera
// (the scene's own, fitted to the model, one a glTF file places, or an explicit pose), the light
// (a glTF file's own, or one placed to show the shadows; then an explicit direction and size).
// The CLI (`--camera`, `--light-dir`, `--light-size`, `--ground`) and the sandbox both stage
// through here, so a frame seen in the sandbox can be reproduced from the command line.
//
//   Result<Scene> s = load_scene("assets/Fox/Fox.gltf");
//   StagingOptions o;  o.aspect = 640.0f / 360.0f;  o.light_size = 2.0f;
//   if (Status st = stage_scene(*s, o); !st) report(st.error());
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "util/error.h"

namespace penumbra::scene {

struct CameraChoice {
  enum class Kind {
    scene,   // built-in scenes: their own camera; glTF files: fitted (the loader's default)
    fitted,  // fit_camera on the model's bounds (without an added ground plane)
    file,    // a camera the glTF file places (Scene::cameras)
    pose,    // position looking at target
  };
  Kind kind = Kind::scene;
  std::string file_camera;             // file: index ("1") or name; empty = the first
  glm::vec3 position{0.0f}, target{0.0f};  // pose, world units
};

struct StagingOptions {
  CameraChoice camera;
  std::optional<glm::vec3> light_direction;  // light -> scene; normalised when applied; an error for a point light
  std::optional<float> light_size;           // emitter diameter, world units (0 = hard)
  bool ground = true;                        // add a plane under a model that has no floor
  float aspect = 16.0f / 9.0f;               // width / height of the frame (fitted cameras)
};

// Stages a scene as load_scene returned it (call once: a second call would see the plane the
// first added as the model's floor). Errors (exit code 2) name the bad choice and the valid ones:
// a file camera the scene does not have, a pose looking at its own position.
Status stage_scene(Scene& scene, const StagingOptions& options);

// The file camera `which` names (index or name; empty = the first), or an error listing them.
Result<size_t> find_file_camera(const Scene& scene, const std::string& which);

// The model's bounds: the scene's, less a plane add_ground_plane added.
Bounds model_bounds(const Scene& scene);

}  // namespace penumbra::scene
