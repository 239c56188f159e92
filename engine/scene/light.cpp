#include "scene/light.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.h"

namespace penumbra::scene {

Light directional_light_for(const Bounds& bounds, const glm::vec3& direction, float size_fraction,
                            float distance_in_radii) {
  Light l;
  l.type = LightType::directional;
  l.direction = glm::normalize(direction);
  const glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
  const float radius = bounds.empty() ? 1.0f : std::max(bounds.radius(), 1e-3f);
  l.position = center - l.direction * (distance_in_radii * radius);
  l.size = size_fraction * 2.0f * radius;
  return l;
}

void emitter_basis(const glm::vec3& d, glm::vec3& tangent, glm::vec3& bitangent) {
  // Pick the world axis least aligned with d so the cross product is well conditioned.
  const glm::vec3 helper = std::abs(d.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  tangent = glm::normalize(glm::cross(helper, d));
  bitangent = glm::cross(d, tangent);
}

static glm::mat4 light_view(const Light& light) {
  glm::vec3 t, b;
  emitter_basis(light.direction, t, b);
  // Use the bitangent as "up" so the shadow map's axes match the emitter basis.
  return glm::lookAt(light.position, light.position + light.direction, b);
}

Status check_spot_angle_degrees(float degrees) {
  if (degrees >= kMinSpotAngleDegrees && degrees <= kMaxSpotAngleDegrees) return {};
  char text[96];
  std::snprintf(text, sizeof text, "spot angle %.4g degrees is outside [%g, %g] (the cone's half-angle)", degrees,
                kMinSpotAngleDegrees, kMaxSpotAngleDegrees);
  return make_error(text);
}

bool light_reaches(const Light& light, const glm::vec3& world) {
  if (light.type != LightType::spot) return true;
  const glm::vec3 to_point = world - light.position;
  const float length = glm::length(to_point);
  if (length <= 0.0f) return true;
  // lighting.comp.glsl's cone: smoothstep(cos(spot_angle), ..., cos(angle off the axis)), 0 at or below
  return glm::dot(to_point / length, glm::normalize(light.direction)) > std::cos(light.spot_angle);
}

const char* light_type_name(LightType type) {
  switch (type) {
    case LightType::directional: return "directional";
    case LightType::spot: return "spot";
    case LightType::point: return "point";
  }
  return "unknown";
}

namespace {

// A point light outside `bounds`: a square perspective frustum from the light towards the
// bounds' centre, just wide enough for every corner. Inside (or too close for
// kMaxPointFrustumHalfAngleDeg) no single frustum sees the scene: `six_faces`.
ShadowFrustum point_frustum(const Light& light, const Bounds& bounds) {
  ShadowFrustum f;
  f.orthographic = false;
  const glm::vec3 p = light.position;
  const bool inside = glm::all(glm::greaterThanEqual(p, bounds.min)) && glm::all(glm::lessThanEqual(p, bounds.max));
  const glm::vec3 to_centre = bounds.center() - p;
  if (inside || glm::length(to_centre) < 1e-6f) {
    f.six_faces = true;
    return f;
  }
  const glm::vec3 dir = glm::normalize(to_centre);
  glm::vec3 t, b;
  emitter_basis(dir, t, b);
  f.view = glm::lookAt(p, p + dir, b);
  float depth_min = std::numeric_limits<float>::max(), depth_max = 0.0f, tan_max = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                      (i & 4) ? bounds.max.z : bounds.min.z);
    const glm::vec3 v = glm::vec3(f.view * glm::vec4(c, 1.0f));
    const float d = -v.z;
    depth_min = std::min(depth_min, d);
    depth_max = std::max(depth_max, d);
    if (d > 0.0f) tan_max = std::max(tan_max, std::max(std::abs(v.x), std::abs(v.y)) / d);
    else tan_max = std::numeric_limits<float>::max();
  }
  const float max_tan = std::tan(glm::radians(kMaxPointFrustumHalfAngleDeg));
  if (tan_max > max_tan) {
    f.six_faces = true;
    return f;
  }
  const float pad = 0.01f * (depth_max - depth_min) + 1e-4f;
  f.far_plane = std::max(depth_max + pad, 1e-2f);
  f.near_plane = std::max(depth_min - pad, 1e-3f * f.far_plane);
  f.tan_half_fov = tan_max * 1.01f;
  f.proj = glm::perspective(2.0f * std::atan(f.tan_half_fov), 1.0f, f.near_plane, f.far_plane);
  f.view_proj = f.proj * f.view;
  return f;
}

}  // namespace

ShadowFrustum shadow_frustum(const Light& light, const Bounds& bounds_in) {
  Bounds bounds = bounds_in;
  if (bounds.empty()) { bounds.extend(glm::vec3(-1.0f)); bounds.extend(glm::vec3(1.0f)); }
  if (light.type == LightType::point) return point_frustum(light, bounds);
  ShadowFrustum f;
  f.view = light_view(light);
  // Bounds corners in light space: x,y across the emitter plane, -z = depth from the light.
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                      (i & 4) ? bounds.max.z : bounds.min.z);
    const glm::vec3 p = glm::vec3(f.view * glm::vec4(c, 1.0f));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const float depth_min = -hi.z, depth_max = -lo.z;  // distances in front of the light
  const float depth_pad = 0.01f * (depth_max - depth_min) + 1e-4f;
  if (light.type == LightType::directional) {
    f.orthographic = true;
    const glm::vec2 c = 0.5f * (glm::vec2(lo) + glm::vec2(hi));
    const float half = 0.5f * std::max(hi.x - lo.x, hi.y - lo.y) * 1.01f;
    f.near_plane = depth_min - depth_pad;
    f.far_plane = depth_max + depth_pad;
    f.proj = glm::ortho(c.x - half, c.x + half, c.y - half, c.y + half, f.near_plane, f.far_plane);
    f.width_world = 2.0f * half;
  } else {
    f.orthographic = false;
    f.far_plane = std::max(depth_max + depth_pad, 1e-2f);
    // A spot inside the scene (a lamp in a room) has geometry behind it, so the fitted near plane
    // would fall to 1e-3 of the far one, where the hyperbolic depth makes a window-depth bias of
    // 2e-4 some 0.3 m at 3 m. Nothing nearer the light's centre than its radius is a caster (it
    // is inside the emitter): the near plane is at least that.
    f.near_plane = std::max({depth_min - depth_pad, 1e-3f * f.far_plane, std::min(light.radius(), 0.5f * f.far_plane)});
    const float fov = std::clamp(2.0f * light.spot_angle, glm::radians(1.0f), glm::radians(170.0f));
    f.proj = glm::perspective(fov, 1.0f, f.near_plane, f.far_plane);
    f.width_world = 0.0f;
    f.tan_half_fov = std::tan(0.5f * fov);
  }
  f.view_proj = f.proj * f.view;
  return f;
}

// PCG-style integer hash (Jarzynski & Olano 2020): cheap, well mixed, identical on CPU and GPU.
static uint32_t pcg_hash(uint32_t v) {
  const uint32_t state = v * 747796405u + 2891336453u;
  const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
static float unit_float(uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

// Shirley & Chiu 1997 concentric square -> disk mapping, u in [0,1)^2 -> unit disk.
static glm::vec2 concentric_disk(glm::vec2 u) {
  const glm::vec2 o = 2.0f * u - 1.0f;
  if (o.x == 0.0f && o.y == 0.0f) return glm::vec2(0.0f);
  constexpr float kQuarterPi = 0.78539816339f;
  float r, theta;
  if (std::abs(o.x) > std::abs(o.y)) {
    r = o.x;
    theta = kQuarterPi * (o.y / o.x);
  } else {
    r = o.y;
    theta = 2.0f * kQuarterPi - kQuarterPi * (o.x / o.y);
  }
  return r * glm::vec2(std::cos(theta), std::sin(theta));
}

std::vector<glm::vec2> unit_disk_samples(int count, uint32_t seed) {
  std::vector<glm::vec2> points;
  if (count <= 0) return points;
  int rows = static_cast<int>(std::sqrt(static_cast<double>(count)));
  while (rows > 1 && count % rows != 0) --rows;
  const int cols = count / rows;
  points.reserve(static_cast<size_t>(count));
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const uint32_t stratum = static_cast<uint32_t>(r * cols + c);
      const uint32_t h1 = pcg_hash(seed * 0x9E3779B9u ^ pcg_hash(stratum * 2u));
      const uint32_t h2 = pcg_hash(h1 ^ pcg_hash(stratum * 2u + 1u));
      const glm::vec2 u((static_cast<float>(c) + unit_float(h1)) / static_cast<float>(cols),
                        (static_cast<float>(r) + unit_float(h2)) / static_cast<float>(rows));
      points.push_back(concentric_disk(u));
    }
  }
  return points;
}

std::vector<glm::vec3> light_sample_points(const Light& light, int count, uint32_t seed) {
  glm::vec3 t, b;
  emitter_basis(glm::normalize(light.direction), t, b);
  const float radius = light.radius();
  std::vector<glm::vec3> points;
  for (const glm::vec2& u : unit_disk_samples(count, seed)) {
    const glm::vec2 d = u * radius;
    points.push_back(light.position + d.x * t + d.y * b);
  }
  return points;
}

glm::vec3 point_light_sample(const Light& light, const glm::vec2& disk, const glm::vec3& receiver) {
  const glm::vec3 facing = light.position - receiver;
  if (light.size <= 0.0f || glm::dot(facing, facing) < 1e-20f) return light.position;
  glm::vec3 t, b;
  emitter_basis(glm::normalize(facing), t, b);
  const glm::vec2 d = disk * light.radius();
  return light.position + d.x * t + d.y * b;
}

}  // namespace penumbra::scene

namespace penumbra::scene {

float emitter_distance(const Light& light, const Bounds& bounds) {
  if (light.type != LightType::directional) return 0.0f;
  const float d = bounds.empty() ? 0.0f : glm::dot(bounds.center() - light.position, glm::normalize(light.direction));
  return std::max(d, std::max(light.radius(), 1e-3f));
}

float blocker_height_scale(const Light& light, const Bounds& bounds) {
  if (bounds.empty()) return 1.0f;
  const glm::vec3 to_centre = bounds.center() - light.position;
  const glm::vec3 ray = light.type == LightType::point && glm::length(to_centre) > 0.0f ? glm::normalize(to_centre)
                                                                                         : glm::normalize(light.direction);
  const float height = std::max(bounds.max.y - bounds.min.y, 1e-6f);
  return height / std::max(std::abs(ray.y), kGrazingRaySine);
}

std::vector<LightSample> light_samples(const Light& light, const Bounds& bounds, int count, uint32_t seed) {
  std::vector<LightSample> out;
  const glm::vec3 dir = glm::normalize(light.direction);
  const float distance = emitter_distance(light, bounds);
  const glm::vec3 target = light.position + distance * dir;
  const std::vector<glm::vec3> points = light_sample_points(light, count, seed);
  const std::vector<glm::vec2> disk = unit_disk_samples(count, seed);
  for (size_t i = 0; i < points.size(); ++i) {
    const glm::vec3& p = points[i];
    LightSample s;
    s.point = p;
    s.disk = disk[i];
    if (light.type == LightType::directional) {
      s.direction = glm::normalize(target - p);
      s.is_point = false;
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace penumbra::scene
