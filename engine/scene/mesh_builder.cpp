#include "scene/mesh_builder.h"

#include <cmath>
#include <utility>

namespace penumbra::scene::build {

static constexpr float kPi = 3.14159265358979f;

static uint32_t push(Mesh& m, const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
  m.vertices.push_back({p, n, uv});
  return static_cast<uint32_t>(m.vertices.size() - 1);
}
static void tri(Mesh& m, uint32_t a, uint32_t b, uint32_t c) { m.indices.insert(m.indices.end(), {a, b, c}); }

void add_ground(Mesh& m, const glm::vec3& c, float sx, float sz) {
  const glm::vec3 n(0, 1, 0);
  const float hx = 0.5f * sx, hz = 0.5f * sz;
  const uint32_t a = push(m, c + glm::vec3(-hx, 0, -hz), n, {0, 0});
  const uint32_t b = push(m, c + glm::vec3(-hx, 0, hz), n, {0, 1});
  const uint32_t d = push(m, c + glm::vec3(hx, 0, hz), n, {1, 1});
  const uint32_t e = push(m, c + glm::vec3(hx, 0, -hz), n, {1, 0});
  tri(m, a, b, d);  // counter-clockwise seen from +Y
  tri(m, a, d, e);
}

void add_box(Mesh& m, const glm::vec3& c, const glm::vec3& h, const glm::mat3& r) {
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      glm::vec3 n(0.0f);
      n[axis] = static_cast<float>(sign);
      glm::vec3 u(0.0f), v(0.0f);
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = 1.0f;
      if (sign < 0) std::swap(u, v);  // keep counter-clockwise winding seen from outside
      const glm::vec3 fc = n * h, fu = u * h, fv = v * h;
      const glm::vec3 wn = r * n;
      const uint32_t a = push(m, c + r * (fc - fu - fv), wn, {0, 0});
      const uint32_t b = push(m, c + r * (fc + fu - fv), wn, {1, 0});
      const uint32_t d = push(m, c + r * (fc + fu + fv), wn, {1, 1});
      const uint32_t e = push(m, c + r * (fc - fu + fv), wn, {0, 1});
      tri(m, a, b, d);
      tri(m, a, d, e);
    }
  }
}

void add_inside_box(Mesh& m, const glm::vec3& c, const glm::vec3& h) {
  const size_t first_vertex = m.vertices.size(), first_index = m.indices.size();
  add_box(m, c, h);
  for (size_t v = first_vertex; v < m.vertices.size(); ++v) m.vertices[v].normal = -m.vertices[v].normal;
  for (size_t t = first_index; t < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
}

void add_sphere(Mesh& m, const glm::vec3& c, float radius, int slices, int stacks) {
  const uint32_t base = static_cast<uint32_t>(m.vertices.size());
  for (int i = 0; i <= stacks; ++i) {
    const float theta = kPi * static_cast<float>(i) / static_cast<float>(stacks);
    for (int j = 0; j <= slices; ++j) {
      const float phi = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(slices);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
      push(m, c + radius * n, n, {static_cast<float>(j) / slices, static_cast<float>(i) / stacks});
    }
  }
  const uint32_t row = static_cast<uint32_t>(slices + 1);
  for (uint32_t i = 0; i < static_cast<uint32_t>(stacks); ++i) {
    for (uint32_t j = 0; j < static_cast<uint32_t>(slices); ++j) {
      const uint32_t a = base + i * row + j, b = a + row;
      if (i != 0) tri(m, a, b, a + 1);                     // skip degenerate triangles at the poles
      if (i + 1 != static_cast<uint32_t>(stacks)) tri(m, a + 1, b, b + 1);
    }
  }
}

void add_cylinder(Mesh& m, const glm::vec3& a, const glm::vec3& b, float radius, int segments) {
  const glm::vec3 axis = glm::normalize(b - a);
  const glm::vec3 helper = std::abs(axis.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 t = glm::normalize(glm::cross(helper, axis)), s = glm::cross(axis, t);
  const uint32_t side = static_cast<uint32_t>(m.vertices.size());
  for (int i = 0; i <= segments; ++i) {
    const float phi = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
    const glm::vec3 n = std::cos(phi) * t + std::sin(phi) * s;
    const float u = static_cast<float>(i) / static_cast<float>(segments);
    push(m, a + radius * n, n, {u, 1});
    push(m, b + radius * n, n, {u, 0});
  }
  for (uint32_t i = 0; i < static_cast<uint32_t>(segments); ++i) {
    const uint32_t k = side + 2 * i;
    tri(m, k, k + 2, k + 1);
    tri(m, k + 1, k + 2, k + 3);
  }
  for (int cap = 0; cap < 2; ++cap) {  // caps as triangle fans
    const glm::vec3 centre = cap ? b : a, n = cap ? axis : -axis;
    const uint32_t c = push(m, centre, n, {0.5f, 0.5f});
    for (int i = 0; i <= segments; ++i) {
      const float phi = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
      push(m, centre + radius * (std::cos(phi) * t + std::sin(phi) * s), n, {0.5f, 0.5f});
    }
    for (uint32_t i = 0; i < static_cast<uint32_t>(segments); ++i) {
      if (cap) tri(m, c, c + 1 + i, c + 2 + i);
      else tri(m, c, c + 2 + i, c + 1 + i);
    }
  }
}

}  // namespace penumbra::scene::build
