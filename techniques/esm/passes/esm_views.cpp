#include "techniques/esm/passes/esm_views.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::esm {
namespace {

// The six face axes and up vectors, in the order of the tiles and of esm_face().
struct Axis {
  glm::vec3 forward, up;
};
constexpr Axis kAxes[6] = {{{1, 0, 0}, {0, -1, 0}}, {{-1, 0, 0}, {0, -1, 0}}, {{0, 1, 0}, {0, 0, 1}},
                           {{0, -1, 0}, {0, 0, -1}}, {{0, 0, 1}, {0, -1, 0}}, {{0, 0, -1}, {0, -1, 0}}};

Result<EsmViews> point_views(const scene::Light& light, const scene::Bounds& bounds_in, int map_size) {
  const int tile = map_size / 3;
  if (tile < kMinFaceSize) {
    return make_error("esm: a point light's six faces need a shadow map of at least " +
                      std::to_string(3 * kMinFaceSize) + " texels (three " + std::to_string(kMinFaceSize) +
                      "-texel tiles a side); got " + std::to_string(map_size));
  }
  scene::Bounds bounds = bounds_in;
  if (bounds.empty()) { bounds.extend(glm::vec3(-1.0f)); bounds.extend(glm::vec3(1.0f)); }
  EsmViews v;
  v.point = true;
  v.orthographic = false;
  v.light = glm::vec4(light.position, 1.0f);
  // Far: the farthest bounds corner; near: 1e-3 of that (float depth keeps the precision).
  float far_plane = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                      (i & 4) ? bounds.max.z : bounds.min.z);
    far_plane = std::max(far_plane, glm::length(c - light.position));
  }
  v.far_plane = std::max(far_plane * 1.01f, 1e-2f);
  v.near_plane = 1e-3f * v.far_plane;
  // 90 degrees over the tile's central T - 2 G texels: tan(half fov) = T / (T - 2 G).
  const float tan_half = static_cast<float>(tile) / static_cast<float>(tile - 2 * kGuardTexels);
  v.texel_scale = 2.0f * tan_half / static_cast<float>(tile);
  const glm::mat4 proj = glm::perspective(2.0f * std::atan(tan_half), 1.0f, v.near_plane, v.far_plane);
  for (int f = 0; f < 6; ++f) {
    EsmFace face;
    face.view_proj = proj * glm::lookAt(light.position, light.position + kAxes[f].forward, kAxes[f].up);
    face.origin = glm::ivec2((f % 3) * tile, (f / 3) * tile);
    face.size = tile;
    v.faces.push_back(face);
  }
  return v;
}

}  // namespace

Result<EsmViews> make_esm_views(const scene::Light& light, const scene::ShadowFrustum& single,
                                const scene::Bounds& bounds, int map_size) {
  if (light.type == scene::LightType::point) return point_views(light, bounds, map_size);
  if (!single.unsupported.empty()) return make_error("esm: " + single.unsupported);
  EsmViews v;
  v.orthographic = single.orthographic;
  v.near_plane = single.near_plane;
  v.far_plane = single.far_plane;
  const float size = static_cast<float>(std::max(map_size, 1));
  v.texel_scale = single.orthographic ? single.width_world / size : 2.0f * single.tan_half_fov / size;
  v.light = light.type == scene::LightType::directional ? glm::vec4(-glm::normalize(light.direction), 0.0f)
                                                        : glm::vec4(light.position, 1.0f);
  v.faces.push_back({single.view_proj, glm::ivec2(0), map_size});
  return v;
}

int esm_face_of(const EsmViews& views, const glm::vec3& world) {
  if (!views.point) return 0;
  const glm::vec3 d = world - glm::vec3(views.light);
  const glm::vec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
  return d.z >= 0.0f ? 4 : 5;
}

}  // namespace penumbra::esm
