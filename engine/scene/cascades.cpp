#include "scene/cascades.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::scene {
namespace {

std::string number(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The farthest view depth at which the scene has anything in front of the camera.
float scene_far(const Camera& camera, const Bounds& bounds) {
  const glm::vec3 forward = camera.forward();
  float far_depth = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                      (i & 4) ? bounds.max.z : bounds.min.z);
    far_depth = std::max(far_depth, glm::dot(c - camera.position, forward));
  }
  return far_depth;
}

// The centre and radius of a sphere around the camera's slice between view depths z0 and z1:
// the centre on the view axis where the near and far corners are equally far (clamped to the
// slice), so the radius depends on the slice's shape only.
void slice_sphere(const Camera& camera, float aspect, float z0, float z1, glm::vec3& centre, float& radius) {
  const float ty = std::tan(0.5f * camera.fov_y), tx = ty * aspect;
  const float k = tx * tx + ty * ty;  // a corner at depth z is z sqrt(k) off the axis
  // |c - z0|^2 + z0^2 k = |z1 - c|^2 + z1^2 k  ->  c = (z0 + z1) / 2 + (z1^2 - z0^2) k / (2 (z1 - z0))
  float c = 0.5f * (z0 + z1) * (1.0f + k);
  c = std::clamp(c, z0, z1);
  radius = std::max(std::sqrt((c - z0) * (c - z0) + z0 * z0 * k), std::sqrt((z1 - c) * (z1 - c) + z1 * z1 * k));
  centre = camera.position + c * camera.forward();
}

}  // namespace

Status check_cascade_settings(const CascadeSettings& s) {
  if (s.count < 1 || s.count > kMaxCascades)
    return make_error("cascades " + std::to_string(s.count) + " is outside 1.." + std::to_string(kMaxCascades),
                      ErrorKind::bad_input);
  if (!(s.split_lambda >= 0.0f && s.split_lambda <= 1.0f))
    return make_error("cascade split lambda " + number(s.split_lambda) + " is outside [0, 1] (0 linear, 1 logarithmic)",
                      ErrorKind::bad_input);
  if (!(s.blend >= 0.0f && s.blend <= 0.5f))
    return make_error("cascade blend band " + number(s.blend) + " is outside [0, 0.5]", ErrorKind::bad_input);
  return {};
}

std::array<float, kMaxCascades + 1> cascade_splits(float n, float f, int count, float lambda) {
  std::array<float, kMaxCascades + 1> z{};
  count = std::clamp(count, 1, kMaxCascades);
  for (int i = 0; i <= count; ++i) {
    const float t = static_cast<float>(i) / static_cast<float>(count);
    z[i] = lambda * n * std::pow(f / n, t) + (1.0f - lambda) * (n + (f - n) * t);
  }
  z[0] = n;
  z[count] = f;
  return z;
}

Result<ShadowCascades> shadow_cascades(const Light& light, const ShadowFrustum& one_map, const Camera& camera,
                                       float aspect, const Bounds& bounds, const CascadeSettings& settings,
                                       int map_size) {
  if (Status s = check_cascade_settings(settings); !s) return s.error();
  ShadowCascades out;
  out.blend = settings.blend;
  out.tint = settings.tint;
  if (settings.count == 1) return out;
  if (light.type != LightType::directional)
    return make_error("cascaded shadow maps are for directional lights; this light is a " +
                          std::string(light_type_name(light.type)) + " light (use one cascade)",
                      ErrorKind::bad_input);
  out.count = settings.count;
  const int tile = map_size / 2;
  const float n = std::max(camera.near_plane, 1e-3f);
  // Rounded up to a step of 2^(1/8): the slices (and so the squares' sizes) stay put while the
  // camera moves, changing only when the scene's far end crosses a step.
  const float ahead = std::max(scene_far(camera, bounds), 2.0f * n);
  const float f = std::min(camera.far_plane, std::exp2(std::ceil(std::log2(ahead) * 8.0f) / 8.0f));
  out.splits = cascade_splits(n, f, out.count, settings.split_lambda);
  // The scene map's square in light space: its x, y range from the ortho projection.
  const glm::mat4 inverse_proj = glm::inverse(one_map.proj);
  const glm::vec2 scene_lo = glm::vec2(inverse_proj * glm::vec4(-1.0f, -1.0f, 0.0f, 1.0f));
  const glm::vec2 scene_centre = scene_lo + 0.5f * glm::vec2(one_map.width_world);
  for (int i = 0; i < out.count; ++i) {
    glm::vec3 centre;
    float radius;
    slice_sphere(camera, aspect, out.splits[i], out.splits[i + 1], centre, radius);
    float side = 2.0f * radius * (1.0f + 2.0f * kCascadeMargin);
    glm::vec2 c = scene_centre;
    if (side < one_map.width_world) {
      const float texel = side / static_cast<float>(tile);
      c = glm::floor(glm::vec2(one_map.view * glm::vec4(centre, 1.0f)) / texel + 0.5f) * texel;
    } else {
      side = one_map.width_world;
    }
    const float half = 0.5f * side;
    const glm::mat4 proj = glm::ortho(c.x - half, c.x + half, c.y - half, c.y + half, one_map.near_plane,
                                      one_map.far_plane);
    out.tiles[i] = {proj * one_map.view, glm::ivec2((i % 2) * tile, (i / 2) * tile), tile};
    out.width_world[i] = side;
  }
  return out;
}

int cascade_of(const ShadowCascades& cascades, const glm::vec3& world) {
  for (int i = 0; i < cascades.count; ++i) {
    const glm::vec4 clip = cascades.tiles[i].view_proj * glm::vec4(world, 1.0f);
    const float edge = std::max(std::abs(clip.x), std::abs(clip.y));
    if (edge <= (i == cascades.count - 1 ? 1.0f : 1.0f - kCascadeMarginOfHalfSide)) return i;
  }
  return cascades.count;
}

}  // namespace penumbra::scene
