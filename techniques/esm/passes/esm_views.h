#pragma once
// Where the extended shadow map looks from (GL-free): one view for a directional or spot light
// (the frame's shadow frustum, the whole map), six for a point light (Bujnak, sections 4 and 6:
// "point lights as six separate spot lights"), each a square tile of the map.
//
// Cascades (scene/cascades.h, a directional light with more than one) are the frame's own tiles,
// each an orthographic view with a texel size of its own; the mask reads a receiver in the
// cascade shadow_common.glsl's cascade_of() picks, as the other techniques do.
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

#include "scene/cascades.h"
#include "scene/light.h"
#include "scene/light_faces.h"
#include "scene/scene.h"
#include "util/error.h"

namespace penumbra::esm {

using EsmFace = scene::LightFace;

struct EsmViews {
  std::vector<EsmFace> faces;   // 1, 2-4 cascades, or 6 for a point light (+X, -X, +Y, -Y, +Z, -Z)
  bool orthographic = true;
  float near_plane = 0.0f, far_plane = 1.0f;  // world units
  // World size of one texel of each face at light distance d: ortho: texel_scale[i];
  // perspective: d * texel_scale[i].
  std::vector<float> texel_scale;
  scene::ShadowCascades cascades;  // count > 1: the faces are these cascades
  glm::vec4 light{0.0f, 1.0f, 0.0f, 0.0f};  // homogeneous: (position, 1), or (-direction, 0) (directional)
  bool point = false;
};

// `single` is the frame's shadow frustum (directional and spot lights); `map_size` the extended
// shadow map's side in texels; `cascades` the frame's (their tiles are in a map of that size).
// Errors: a point-light map too small for six faces.
Result<EsmViews> make_esm_views(const scene::Light& light, const scene::ShadowFrustum& single,
                                const scene::Bounds& bounds, int map_size,
                                const scene::ShadowCascades& cascades = {});

// The face a world position belongs to (scene::light_face_of its direction from the light; for
// cascades scene::cascade_of, the last where none holds it), 0 for one-view lights; the same
// rules as esm_face() in esm_views.glsl and cascade_of() in shadow_common.glsl.
int esm_face_of(const EsmViews& views, const glm::vec3& world);

}  // namespace penumbra::esm
