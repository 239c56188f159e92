#include "sample_view.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::reference {

namespace {

scene::Bounds non_empty(const scene::Bounds& b) {
  scene::Bounds out = b;
  if (out.empty()) { out.extend(glm::vec3(-1.0f)); out.extend(glm::vec3(1.0f)); }
  return out;
}

// A parallel light of direction `dir` (light -> scene): orthographic, square, fitted to the bounds.
SampleView parallel_view(const scene::Bounds& bounds, const glm::vec3& dir) {
  glm::vec3 tangent, bitangent;
  scene::emitter_basis(dir, tangent, bitangent);
  const glm::vec3 centre = bounds.center();
  const float radius = std::max(bounds.radius(), 1e-3f);
  const glm::mat4 view = glm::lookAt(centre - 2.0f * radius * dir, centre, bitangent);
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                      (i & 4) ? bounds.max.z : bounds.min.z);
    const glm::vec3 p = glm::vec3(view * glm::vec4(c, 1.0f));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const float pad = 0.01f * (hi.z - lo.z) + 1e-4f;
  const glm::vec2 c = 0.5f * (glm::vec2(lo) + glm::vec2(hi));
  const float half = 0.5f * std::max(hi.x - lo.x, hi.y - lo.y) * 1.01f;
  const glm::mat4 proj = glm::ortho(c.x - half, c.x + half, c.y - half, c.y + half, -hi.z - pad, -lo.z + pad);
  return {proj * view, 0.0f, 2.0f * half};
}

}  // namespace

SampleView sample_view(const scene::Light& light, const scene::Bounds& bounds_in, const scene::LightSample& sample) {
  const scene::Bounds bounds = non_empty(bounds_in);
  if (!sample.is_point) return parallel_view(bounds, glm::normalize(sample.direction));
  const glm::vec3 eye = sample.point;
  glm::vec3 tangent, bitangent;
  const glm::vec3 dir = glm::normalize(light.direction);
  scene::emitter_basis(dir, tangent, bitangent);
  // Same orientation as scene::shadow_frustum: bitangent up, so map axes follow the emitter basis.
  const glm::mat4 view = glm::lookAt(eye, eye + dir, bitangent);

  glm::vec3 corners[8];
  float depth_min = std::numeric_limits<float>::max(), depth_max = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                      (i & 4) ? bounds.max.z : bounds.min.z);
    corners[i] = glm::vec3(view * glm::vec4(c, 1.0f));
    depth_min = std::min(depth_min, -corners[i].z);
    depth_max = std::max(depth_max, -corners[i].z);
  }
  // Depth range in world units in front of the eye, padded 1% like shadow_frustum.
  const float pad = 0.01f * std::max(depth_max - depth_min, 0.0f) + 1e-4f;
  const float far_plane = std::max(depth_max + pad, 1e-2f);
  const float near_plane = std::max(depth_min - pad, 1e-3f * far_plane);

  // Tangent-space extent (x / depth, y / depth) of the corners; a corner at or behind the near
  // plane (light inside the bounds) opens the frustum to the widest allowed angle.
  const float max_tan = std::tan(glm::radians(kMaxSampleMapHalfAngleDeg));
  glm::vec2 lo(max_tan), hi(-max_tan);
  for (const glm::vec3& c : corners) {
    const float d = -c.z;
    if (d <= near_plane) {
      lo = glm::vec2(-max_tan);
      hi = glm::vec2(max_tan);
      break;
    }
    const glm::vec2 t(c.x / d, c.y / d);
    lo = glm::min(lo, t);
    hi = glm::max(hi, t);
  }
  lo = glm::max(lo, glm::vec2(-max_tan));
  hi = glm::min(hi, glm::vec2(max_tan));
  const glm::vec2 margin = 0.005f * (hi - lo) + 1e-6f;  // keep border texels off the geometry
  lo -= margin;
  hi += margin;
  const glm::mat4 proj = glm::frustum(lo.x * near_plane, hi.x * near_plane, lo.y * near_plane, hi.y * near_plane,
                                      near_plane, far_plane);
  return {proj * view, std::max(hi.x - lo.x, hi.y - lo.y), 0.0f};
}

int progressive_index(int k, int count) {
  if (count <= 1) return 0;
  int stride = std::max(1, static_cast<int>(std::lround(count * 0.6180339887)));
  while (std::gcd(stride, count) != 1) ++stride;
  return static_cast<int>((static_cast<long long>(k) * stride) % count);
}

}  // namespace penumbra::reference
