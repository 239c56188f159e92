#include "techniques/esm/passes/esm_views.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::esm {
namespace {

Result<EsmViews> point_views(const scene::Light& light, const scene::Bounds& bounds, int map_size) {
  Result<scene::PointLightFaces> faces = scene::point_light_faces(light, bounds, map_size);
  if (!faces) return make_error("esm: " + faces.error().message);
  EsmViews v;
  v.point = true;
  v.orthographic = false;
  v.light = glm::vec4(light.position, 1.0f);
  v.near_plane = faces->near_plane;
  v.far_plane = faces->far_plane;
  v.texel_scale = 2.0f * faces->tan_half_fov / static_cast<float>(faces->tile);
  v.faces.assign(faces->faces.begin(), faces->faces.end());
  return v;
}

}  // namespace

Result<EsmViews> make_esm_views(const scene::Light& light, const scene::ShadowFrustum& single,
                                const scene::Bounds& bounds, int map_size) {
  if (light.type == scene::LightType::point) return point_views(light, bounds, map_size);
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
  return scene::light_face_of(world - glm::vec3(views.light));
}

}  // namespace penumbra::esm
