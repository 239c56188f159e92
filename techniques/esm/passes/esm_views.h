#pragma once
// Where the extended shadow map looks from (GL-free): one view for a directional or spot light
// (the frame's shadow frustum, the whole map), six for a point light (Bujnak, sections 4 and 6:
// "point lights as six separate spot lights"), each a square tile of the map.
//
// Point lights use the shared six-face layout (scene/light_faces.h): each face a square tile of
// the map, wider than 90 degrees by scene::kFaceGuardTexels so that everything the shadow test
// reads around a receiver (the 2x2 bilinear footprint, the silhouette quads of edges up to the
// quad band away) was rendered into the same tile: no lookup crosses a face boundary.
//
//   Result<EsmViews> v = make_esm_views(frame.light, frame.shadow, bounds, esm_texture.width());
//   for (const EsmFace& f : v->faces) { glViewport(f.origin.x, f.origin.y, f.size, f.size); draw(f.view_proj); }
#include <vector>

#include <glm/glm.hpp>

#include "scene/light.h"
#include "scene/light_faces.h"
#include "scene/scene.h"
#include "util/error.h"

namespace penumbra::esm {

using EsmFace = scene::LightFace;

struct EsmViews {
  std::vector<EsmFace> faces;   // 1, or 6 for a point light (+X, -X, +Y, -Y, +Z, -Z)
  bool orthographic = true;
  float near_plane = 0.0f, far_plane = 1.0f;  // world units
  // World size of one texel at light distance d: ortho: texel_scale; perspective: d * texel_scale.
  float texel_scale = 0.0f;
  glm::vec4 light{0.0f, 1.0f, 0.0f, 0.0f};  // homogeneous: (position, 1), or (-direction, 0) (directional)
  bool point = false;
};

// `single` is the frame's shadow frustum (directional and spot lights); `map_size` the extended
// shadow map's side in texels. Errors: a point-light map too small for six faces.
Result<EsmViews> make_esm_views(const scene::Light& light, const scene::ShadowFrustum& single,
                                const scene::Bounds& bounds, int map_size);

// The face a world position belongs to (scene::light_face_of its direction from the light), 0
// for one-view lights; the same rule as esm_face() in esm_views.glsl.
int esm_face_of(const EsmViews& views, const glm::vec3& world);

}  // namespace penumbra::esm
