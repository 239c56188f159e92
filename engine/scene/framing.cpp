#include "scene/framing.h"

#include <algorithm>
#include <cmath>

namespace penumbra::scene {

namespace {

Bounds non_empty(const Bounds& b) {
  if (!b.empty()) return b;
  Bounds unit;
  unit.extend(glm::vec3(-1.0f));
  unit.extend(glm::vec3(1.0f));
  return unit;
}

glm::vec3 normalized_or(const glm::vec3& v, const glm::vec3& fallback) {
  return glm::length(v) > 1e-6f ? glm::normalize(v) : fallback;
}

}  // namespace

Camera fit_camera(const Bounds& bounds_in, float aspect, const glm::vec3& view_direction, float fov_y, float margin) {
  const Bounds bounds = non_empty(bounds_in);
  const glm::vec3 forward = normalized_or(view_direction, glm::normalize(kDefaultViewDirection));
  // The view basis Camera::view() builds (world up +Y), so the fit matches what is drawn.
  const glm::vec3 right = normalized_or(glm::cross(forward, glm::vec3(0, 1, 0)), glm::vec3(1, 0, 0));
  const glm::vec3 up = glm::cross(right, forward);
  const float tan_v = std::tan(0.5f * fov_y) * (1.0f - 2.0f * std::clamp(margin, 0.0f, 0.4f));
  const float tan_h = tan_v * std::max(aspect, 1e-3f);
  const glm::vec3 center = bounds.center();
  // The camera sits at center - forward * d; a corner at view depth d + z must satisfy
  // |x| <= (d + z) tan_h and |y| <= (d + z) tan_v.
  float distance = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                      (i & 4) ? bounds.max.z : bounds.min.z);
    const glm::vec3 p = c - center;
    const float need = std::max(std::abs(glm::dot(p, right)) / tan_h, std::abs(glm::dot(p, up)) / tan_v) -
                       glm::dot(p, forward);
    distance = std::max(distance, need);
  }
  // Never inside the bounding sphere (a flat model seen edge-on needs almost no distance).
  distance = std::max(distance, 1.05f * std::max(bounds.radius(), 1e-3f));
  Camera camera = Camera::look_at(center - forward * distance, center, fov_y);
  fit_clip_planes(camera, bounds);
  return camera;
}

void fit_clip_planes(Camera& camera, const Bounds& bounds_in) {
  const Bounds bounds = non_empty(bounds_in);
  const float radius = std::max(bounds.radius(), 1e-3f);
  const float distance = glm::length(camera.position - bounds.center());
  camera.near_plane = 0.002f * radius;
  camera.far_plane = std::max(distance + radius, 0.0f) + 6.0f * radius;
}

glm::vec3 default_light_direction(const glm::vec3& view_direction) {
  const glm::vec3 v = normalized_or(view_direction, glm::normalize(kDefaultViewDirection));
  // Horizontal part of the view, turned 60 degrees about +Y: light travelling that way lights the
  // model from behind-left and throws its shadow forward-right, towards the camera.
  glm::vec2 h(v.x, v.z);
  h = glm::length(h) > 1e-4f ? glm::normalize(h) : glm::vec2(0.0f, -1.0f);
  const float a = glm::radians(60.0f);
  const glm::vec2 turned(h.x * std::cos(a) - h.y * std::sin(a), h.x * std::sin(a) + h.y * std::cos(a));
  // Travelling towards the camera (-turned), 50 degrees below the horizon.
  const float elevation = glm::radians(50.0f);
  return glm::normalize(glm::vec3(-turned.x * std::cos(elevation), -std::sin(elevation), -turned.y * std::cos(elevation)));
}

Light default_light(const Bounds& bounds, const glm::vec3& view_direction) {
  // directional_light_for's disk at 2 radii with diameter fraction f has angular size f.
  return directional_light_for(non_empty(bounds), default_light_direction(view_direction), kDefaultLightAngle);
}

std::optional<Light> file_light(const Scene& scene) {
  const SceneLight* chosen = nullptr;
  for (LightType type : {LightType::directional, LightType::spot, LightType::point}) {
    for (const SceneLight& l : scene.lights)
      if (l.light.type == type) {
        chosen = &l;
        break;
      }
    if (chosen) break;
  }
  if (!chosen) return std::nullopt;
  const Bounds bounds = non_empty(scene.bounds);
  Light light = chosen->light;
  if (light.type == LightType::directional) {
    Light placed = directional_light_for(bounds, light.direction, kDefaultLightAngle);
    light.position = placed.position;
    light.size = placed.size;
  } else {
    const float distance = std::max(glm::length(bounds.center() - light.position), 1e-3f * bounds.radius());
    light.size = kDefaultLightAngle * distance;
  }
  return light;
}

void set_light_direction(Light& light, glm::vec3 direction, const Bounds& bounds) {
  if (!(glm::length(direction) > 1e-6f)) return;
  direction = glm::normalize(direction);
  if (light.type == LightType::directional && !bounds.empty()) {
    const glm::vec3 c = bounds.center();
    const float distance = std::max(glm::length(light.position - c), 2.0f * bounds.radius());
    light.position = c - direction * distance;
  }
  light.direction = direction;
}

Camera camera_from_node(const glm::mat4& world, float yfov, float znear, float zfar) {
  const glm::vec3 position(world[3]);
  const glm::vec3 forward = normalized_or(glm::mat3(world) * glm::vec3(0, 0, -1), glm::vec3(0, 0, -1));
  const float fov = yfov > 0.0f && std::isfinite(yfov) ? std::clamp(yfov, glm::radians(1.0f), glm::radians(170.0f))
                                                      : glm::radians(50.0f);
  const float near_plane = znear > 0.0f ? znear : 0.05f;
  const float far_plane = zfar > near_plane ? zfar : near_plane * 1e4f;
  return Camera::look_at(position, position + forward, fov, near_plane, far_plane);
}

}  // namespace penumbra::scene
