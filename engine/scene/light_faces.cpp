#include "scene/light_faces.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::scene {
namespace {

// The face axes and up vectors, in the order of the tiles and of light_face_of().
struct Axis {
  glm::vec3 forward, up;
};
constexpr Axis kAxes[6] = {{{1, 0, 0}, {0, -1, 0}}, {{-1, 0, 0}, {0, -1, 0}}, {{0, 1, 0}, {0, 0, 1}},
                           {{0, -1, 0}, {0, 0, -1}}, {{0, 0, 1}, {0, -1, 0}}, {{0, 0, -1}, {0, -1, 0}}};

}  // namespace

Result<PointLightFaces> point_light_faces(const Light& light, const Bounds& bounds_in, int map_size) {
  const int tile = map_size / 3;
  if (tile < kMinFaceSize) {
    return make_error("a point light's six faces need a shadow map of at least " + std::to_string(3 * kMinFaceSize) +
                      " texels (three " + std::to_string(kMinFaceSize) + "-texel tiles a side); got " +
                      std::to_string(map_size));
  }
  Bounds bounds = bounds_in;
  if (bounds.empty()) { bounds.extend(glm::vec3(-1.0f)); bounds.extend(glm::vec3(1.0f)); }
  PointLightFaces v;
  float far_plane = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                      (i & 4) ? bounds.max.z : bounds.min.z);
    far_plane = std::max(far_plane, glm::length(c - light.position));
  }
  v.far_plane = std::max(far_plane * 1.01f, 1e-2f);
  v.near_plane = 1e-3f * v.far_plane;  // float depth keeps the precision
  v.tile = tile;
  // 90 degrees over the tile's central T - 2 G texels.
  v.tan_half_fov = static_cast<float>(tile) / static_cast<float>(tile - 2 * kFaceGuardTexels);
  const glm::mat4 proj = glm::perspective(2.0f * std::atan(v.tan_half_fov), 1.0f, v.near_plane, v.far_plane);
  for (int f = 0; f < 6; ++f) {
    LightFace& face = v.faces[f];
    face.view_proj = proj * glm::lookAt(light.position, light.position + kAxes[f].forward, kAxes[f].up);
    face.origin = glm::ivec2((f % 3) * tile, (f / 3) * tile);
    face.size = tile;
  }
  return v;
}

int light_face_of(const glm::vec3& d) {
  const glm::vec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
  return d.z >= 0.0f ? 4 : 5;
}

}  // namespace penumbra::scene
