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
  v.faces.assign(faces->faces.begin(), faces->faces.end());
  v.texel_scale.assign(6, 2.0f * faces->tan_half_fov / static_cast<float>(faces->tile));
  return v;
}

}  // namespace

Result<EsmViews> make_esm_views(const scene::Light& light, const scene::ShadowFrustum& single,
                                const scene::Bounds& bounds, int map_size, const scene::ShadowCascades& cascades) {
  if (light.type == scene::LightType::point) return point_views(light, bounds, map_size);
  EsmViews v;
  v.orthographic = single.orthographic;
  v.near_plane = single.near_plane;
  v.far_plane = single.far_plane;
  v.light = light.type == scene::LightType::directional ? glm::vec4(-glm::normalize(light.direction), 0.0f)
                                                        : glm::vec4(light.position, 1.0f);
  if (cascades.count > 1) {  // the frame's tiles: the same near and far, a texel size each
    v.cascades = cascades;
    for (int i = 0; i < cascades.count; ++i) {
      const scene::LightFace& t = cascades.tiles[i];
      if (t.origin.x + t.size > map_size || t.origin.y + t.size > map_size)
        return make_error("esm: cascade tiles of a larger map than its " + std::to_string(map_size) + " texels",
                          ErrorKind::internal);
      v.faces.push_back(t);
      v.texel_scale.push_back(cascades.width_world[i] / static_cast<float>(t.size));
    }
    return v;
  }
  const float size = static_cast<float>(std::max(map_size, 1));
  v.texel_scale.push_back(single.orthographic ? single.width_world / size : 2.0f * single.tan_half_fov / size);
  v.faces.push_back({single.view_proj, glm::ivec2(0), map_size});
  return v;
}

int esm_face_of(const EsmViews& views, const glm::vec3& world) {
  if (views.cascades.count > 1) return std::min(scene::cascade_of(views.cascades, world), views.cascades.count - 1);
  if (!views.point) return 0;
  return scene::light_face_of(world - glm::vec3(views.light));
}

}  // namespace penumbra::esm
