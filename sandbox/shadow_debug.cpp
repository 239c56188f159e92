#include "sandbox/shadow_debug.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace penumbra::sandbox {

std::vector<Segment> frustum_segments(const scene::ShadowFrustum& f) {
  const glm::mat4 inv = glm::inverse(f.view_proj);
  glm::vec3 c[8];
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 p = inv * glm::vec4((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f, 1.0f);
    c[i] = glm::vec3(p) / p.w;
  }
  std::vector<Segment> out;
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) out.push_back({c[i], c[i | bit]});
  return out;
}

std::vector<glm::vec3> emitter_outline(const scene::Light& light, int count) {
  glm::vec3 t, b;
  scene::emitter_basis(glm::normalize(light.direction), t, b);
  std::vector<glm::vec3> out;
  const float r = std::max(light.radius(), 1e-4f);
  for (int i = 0; i < count; ++i) {
    const float a = glm::two_pi<float>() * float(i) / float(count);
    out.push_back(light.position + r * (std::cos(a) * t + std::sin(a) * b));
  }
  return out;
}

std::vector<Segment> emitter_segments(const scene::Light& light, int segments) {
  const std::vector<glm::vec3> ring = emitter_outline(light, std::max(segments, 3));
  std::vector<Segment> out;
  for (size_t i = 0; i < ring.size(); ++i) out.push_back({ring[i], ring[(i + 1) % ring.size()]});
  const float arrow = std::max(2.0f * light.radius(), 0.2f);
  out.push_back({light.position, light.position + glm::normalize(light.direction) * arrow});
  return out;
}

std::vector<std::pair<glm::vec2, glm::vec2>> project_segments(const std::vector<Segment>& segments,
                                                              const scene::Camera& camera, int width, int height) {
  const glm::mat4 vp = camera.projection(float(width) / float(std::max(height, 1))) * camera.view();
  auto to_pixel = [&](const glm::vec4& c) {
    return glm::vec2((c.x / c.w * 0.5f + 0.5f) * width, (0.5f - c.y / c.w * 0.5f) * height);
  };
  std::vector<std::pair<glm::vec2, glm::vec2>> out;
  const float eps = 1e-5f;
  for (const Segment& s : segments) {
    glm::vec4 a = vp * glm::vec4(s.first, 1.0f), b = vp * glm::vec4(s.second, 1.0f);
    // Clip against the near plane (z > -w) so a segment passing behind the camera is cut.
    const float da = a.z + a.w, db = b.z + b.w;
    if (da < eps && db < eps) continue;
    if (da < eps) a = a + (b - a) * ((eps - da) / (db - da));
    if (db < eps) b = b + (a - b) * ((eps - db) / (da - db));
    if (a.w <= 0.0f || b.w <= 0.0f) continue;
    out.push_back({to_pixel(a), to_pixel(b)});
  }
  return out;
}

std::vector<glm::vec2> blocker_search_region(const glm::vec3& receiver, const scene::Light& light,
                                             const scene::ShadowFrustum& f, int samples) {
  auto uv_of = [&](const glm::vec3& p) -> std::optional<glm::vec2> {
    const glm::vec4 c = f.view_proj * glm::vec4(p, 1.0f);
    if (c.w <= 1e-6f) return std::nullopt;
    return glm::vec2(c.x / c.w * 0.5f + 0.5f, c.y / c.w * 0.5f + 0.5f);
  };
  const std::optional<glm::vec2> r = uv_of(receiver);
  if (!r || r->x < 0.0f || r->y < 0.0f || r->x > 1.0f || r->y > 1.0f) return {};
  std::vector<glm::vec2> pts{*r};
  for (const glm::vec3& e : emitter_outline(light, std::max(samples, 3))) {
    // Perspective maps see the emitter only up to the near plane: walk from the receiver towards
    // the emitter point and stop at the near plane (distance along the light's direction).
    glm::vec3 q = e;
    if (!f.orthographic) {
      const glm::vec3 d = glm::normalize(light.direction);
      const float near_at = glm::dot(light.position, d) + f.near_plane;
      const float pr = glm::dot(receiver, d), pe = glm::dot(e, d);
      if (pe < near_at && pr > near_at) q = receiver + (e - receiver) * ((pr - near_at) / (pr - pe));
    }
    if (auto uv = uv_of(q)) pts.push_back(*uv);
  }
  // Andrew's monotone chain.
  std::sort(pts.begin(), pts.end(), [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  auto cross = [](const glm::vec2& o, const glm::vec2& a, const glm::vec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<glm::vec2> hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0.0f) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0.0f) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

float light_distance(const scene::ShadowFrustum& f, float depth) {
  const float n = f.near_plane, fa = f.far_plane;
  if (f.orthographic) return n + depth * (fa - n);
  const float z = depth * 2.0f - 1.0f;
  return 2.0f * n * fa / (fa + n - z * (fa - n));
}

float shadow_depth(const scene::ShadowFrustum& f, const glm::vec3& p) {
  const glm::vec4 c = f.view_proj * glm::vec4(p, 1.0f);
  return c.z / c.w * 0.5f + 0.5f;
}

float penumbra_width(float light_size, float receiver_distance, float blocker_distance) {
  if (!(blocker_distance > 0.0f) || receiver_distance <= blocker_distance) return 0.0f;
  return light_size * (receiver_distance - blocker_distance) / blocker_distance;
}

}  // namespace penumbra::sandbox
