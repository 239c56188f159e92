#include "scene/staging.h"

#include <cstdlib>

#include "scene/framing.h"
#include "scene/ground_plane.h"

namespace penumbra::scene {

namespace {

std::string camera_list(const Scene& scene) {
  std::string list;
  for (size_t i = 0; i < scene.cameras.size(); ++i)
    list += (list.empty() ? "" : ", ") + std::to_string(i) +
            (scene.cameras[i].name.empty() ? "" : " '" + scene.cameras[i].name + "'");
  return list;
}

}  // namespace

Bounds model_bounds(const Scene& scene) {
  Bounds b;
  for (const Instance& inst : scene.instances) {
    if (inst.mesh >= scene.meshes.size() || scene.meshes[inst.mesh].name == kGroundPlaneName) continue;
    for (const Vertex& v : scene.meshes[inst.mesh].vertices) b.extend(glm::vec3(inst.world * glm::vec4(v.position, 1.0f)));
  }
  return b.empty() ? scene.bounds : b;
}

Result<size_t> find_file_camera(const Scene& scene, const std::string& which) {
  if (scene.cameras.empty())
    return make_error("scene '" + scene.name + "' places no camera of its own (a glTF node with a perspective "
                      "camera); use a fitted camera or a pose x,y,z:tx,ty,tz");
  if (which.empty()) return size_t{0};
  char* end = nullptr;
  const long index = std::strtol(which.c_str(), &end, 10);
  if (end && *end == '\0' && !which.empty()) {
    if (index >= 0 && static_cast<size_t>(index) < scene.cameras.size()) return static_cast<size_t>(index);
  } else {
    for (size_t i = 0; i < scene.cameras.size(); ++i)
      if (scene.cameras[i].name == which) return i;
  }
  return make_error("scene '" + scene.name + "' has no camera '" + shortened(which) + "'; its cameras: " +
                    camera_list(scene));
}

Status stage_scene(Scene& scene, const StagingOptions& o) {
  const bool from_file = !scene.source_file.empty();
  const Bounds model = model_bounds(scene);
  if (o.ground && !has_added_ground_plane(scene) && !has_ground(scene)) add_ground_plane(scene);

  switch (o.camera.kind) {
    case CameraChoice::Kind::scene:
      if (from_file) scene.camera = fit_camera(model, o.aspect);
      break;
    case CameraChoice::Kind::fitted: scene.camera = fit_camera(model, o.aspect); break;
    case CameraChoice::Kind::file: {
      Result<size_t> i = find_file_camera(scene, o.camera.file_camera);
      if (!i) return i.error();
      scene.camera = scene.cameras[*i].camera;
      break;
    }
    case CameraChoice::Kind::pose:
      if (glm::length(o.camera.target - o.camera.position) < 1e-6f)
        return make_error("camera pose: the target equals the position (give x,y,z:tx,ty,tz with distinct points)");
      scene.camera = Camera::look_at(o.camera.position, o.camera.target, scene.camera.fov_y);
      break;
  }
  // Clip planes fitted to what is drawn (with the ground plane), whichever camera was chosen:
  // a file's near plane or a built-in's far plane must not clip the model when the camera moves.
  if (from_file || o.camera.kind != CameraChoice::Kind::scene) fit_clip_planes(scene.camera, scene.bounds);

  if (from_file) {
    if (std::optional<Light> own = file_light(scene)) scene.light = *own;
    else scene.light = default_light(scene.bounds, scene.camera.forward());
  }
  if (o.light_direction) {
    // A point light has no direction (scene/light.h): turning it would silently change nothing.
    if (scene.light.type == LightType::point)
      return make_error("a light direction was given, but the scene's light is a point light, which shines in every "
                        "direction from its position (a direction turns directional and spot lights only)");
    set_light_direction(scene.light, *o.light_direction, scene.bounds);
  }
  if (o.light_size) {
    if (!(*o.light_size >= 0.0f))
      return make_error("light size must be >= 0 (emitter diameter, world units)");
    scene.light.size = *o.light_size;
  }
  return {};
}

}  // namespace penumbra::scene
