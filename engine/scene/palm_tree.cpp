#include "scene/palm_tree.h"

#include <cmath>

#include "scene/mesh_builder.h"

namespace penumbra::scene {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr int kImageLength = 256;  // texels along the frond (u)
constexpr int kImageWidth = 64;    // texels across (v)
constexpr int kLeaflets = 14;      // leaflet pairs along the frond

// Frond opacity at (u, v) in [0, 1]^2 (see palm_frond_image()).
bool frond_opaque(float u, float v) {
  const float across = std::abs(v - 0.5f) * 2.0f;  // 0 on the midrib, 1 at the texture edge
  if (across < 0.06f) return u < 0.98f;           // midrib
  // Outline: narrow at the base, widest a third of the way, pointed at the tip.
  const float outline = std::pow(std::sin(kPi * std::min(u, 0.999f)), 0.6f) * (1.0f - 0.35f * u);
  if (across > outline || u < 0.04f) return false;
  // Leaflets slant towards the tip as they leave the midrib; each takes 55% of its period.
  const float phase = u * static_cast<float>(kLeaflets) - 0.6f * across;
  return phase - std::floor(phase) < 0.55f;
}

uint32_t push(Mesh& m, const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
  m.vertices.push_back({p, n, uv});
  return static_cast<uint32_t>(m.vertices.size() - 1);
}

// A quad from a0/a1 (the edge at u0) to b0/b1 (the edge at u1), v = 0 on the *0 side.
void add_quad(Mesh& m, glm::vec3 a0, glm::vec3 a1, glm::vec3 b0, glm::vec3 b1, float u0, float u1) {
  const glm::vec3 n = glm::normalize(glm::cross(a1 - a0, b0 - a0));  // the side the crown's top shows
  const uint32_t i0 = push(m, a0, n, {u0, 0.0f}), i1 = push(m, a1, n, {u0, 1.0f});
  const uint32_t i2 = push(m, b1, n, {u1, 1.0f}), i3 = push(m, b0, n, {u1, 0.0f});
  m.indices.insert(m.indices.end(), {i0, i1, i2, i0, i2, i3});
}

}  // namespace

Image palm_frond_image() {
  Image img;
  img.name = "palm_frond";
  img.width = kImageLength;
  img.height = kImageWidth;
  img.pixels.resize(static_cast<size_t>(kImageLength) * kImageWidth * 4);
  for (int y = 0; y < kImageWidth; ++y)
    for (int x = 0; x < kImageLength; ++x) {
      const float u = (static_cast<float>(x) + 0.5f) / kImageLength, v = (static_cast<float>(y) + 0.5f) / kImageWidth;
      uint8_t* p = &img.pixels[(static_cast<size_t>(y) * kImageLength + x) * 4];
      p[0] = static_cast<uint8_t>(60 + 40 * u);
      p[1] = static_cast<uint8_t>(140 - 30 * u);
      p[2] = 50;
      p[3] = frond_opaque(u, v) ? 255 : 0;
    }
  return img;
}

namespace build {

void add_palm(Mesh& trunk, Mesh& fronds, const PalmTree& palm) {
  // Trunk: four cylinders along a curve that leans more towards the top.
  const float lean = glm::radians(palm.lean_degrees), az = glm::radians(palm.lean_azimuth);
  const glm::vec3 side(std::cos(az), 0.0f, std::sin(az));
  auto trunk_point = [&](float t) {  // t in [0, 1] base to top
    return palm.base + glm::vec3(0.0f, palm.height * t, 0.0f) + side * (palm.height * std::tan(lean) * t * t);
  };
  for (int i = 0; i < 4; ++i) {
    const float t0 = static_cast<float>(i) / 4.0f, t1 = static_cast<float>(i + 1) / 4.0f;
    add_cylinder(trunk, trunk_point(t0), trunk_point(t1), 0.14f - 0.03f * t0, 10);
  }
  // Crown: each frond rises 15 degrees over its first 40%, then droops 40 degrees.
  const glm::vec3 top = trunk_point(1.0f);
  for (int k = 0; k < palm.fronds; ++k) {
    const float phi = glm::radians(palm.crown_phase) + 2.0f * kPi * static_cast<float>(k) / static_cast<float>(palm.fronds);
    const glm::vec3 out(std::cos(phi), 0.0f, std::sin(phi)), across(-std::sin(phi), 0.0f, std::cos(phi));
    const float rise = glm::radians(15.0f), droop = glm::radians(-40.0f);
    const glm::vec3 d0 = std::cos(rise) * out + glm::vec3(0, std::sin(rise), 0);
    const glm::vec3 d1 = std::cos(droop) * out + glm::vec3(0, std::sin(droop), 0);
    const glm::vec3 mid = top + 0.4f * palm.frond_length * d0, tip = mid + 0.6f * palm.frond_length * d1;
    const glm::vec3 half = 0.5f * palm.frond_width * across;
    add_quad(fronds, top - half, top + half, mid - half, mid + half, 0.0f, 0.4f);
    add_quad(fronds, mid - half, mid + half, tip - half, tip + half, 0.4f, 1.0f);
  }
}

}  // namespace build
}  // namespace penumbra::scene
