#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace penumbra::scene {

size_t Scene::triangle_count() const {
  size_t n = 0;
  for (const Instance& inst : instances)
    if (inst.mesh < meshes.size()) n += meshes[inst.mesh].triangle_count();
  return n;
}

Bounds compute_bounds(const Scene& scene) {
  Bounds b;
  for (const Instance& inst : scene.instances) {
    if (inst.mesh >= scene.meshes.size()) continue;
    for (const Vertex& v : scene.meshes[inst.mesh].vertices)
      b.extend(glm::vec3(inst.world * glm::vec4(v.position, 1.0f)));
  }
  return b;
}

Camera frame_bounds(const Bounds& bounds, float fov_y) {
  const glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
  const float radius = bounds.empty() ? 1.0f : std::max(bounds.radius(), 1e-3f);
  // Distance at which the bounding sphere fits the vertical field of view, plus a margin.
  const float distance = 1.1f * radius / std::sin(0.5f * fov_y);
  const glm::vec3 view_dir = glm::normalize(glm::vec3(0.0f, -0.45f, -1.0f));
  const glm::vec3 eye = center - view_dir * distance;
  return Camera::look_at(eye, center, fov_y, std::max(distance - radius * 1.5f, distance * 0.01f),
                         distance + radius * 1.5f);
}

float fit_scene_scale(Scene& scene) {
  // In double: a float length of a 1e30 extent overflows, of a 1e-30 one underflows to 0.
  const double radius = 0.5 * glm::length(glm::dvec3(scene.bounds.max) - glm::dvec3(scene.bounds.min));
  if (!(radius > 0.0) || (radius >= kMinSceneRadius && radius <= kMaxSceneRadius)) return 1.0f;
  const float s = static_cast<float>(kScaledSceneRadius / radius);
  const glm::mat4 scale = glm::scale(glm::mat4(1.0f), glm::vec3(s));
  for (Instance& i : scene.instances) i.world = scale * i.world;
  for (SceneLight& l : scene.lights) {
    l.light.position *= s;
    l.range *= s;
  }
  for (SceneCamera& c : scene.cameras) {
    c.camera.position *= s;
    c.camera.near_plane *= s;
    c.camera.far_plane *= s;
  }
  scene.bounds = compute_bounds(scene);
  return s;
}

}  // namespace penumbra::scene
