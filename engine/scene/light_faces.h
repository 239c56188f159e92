#pragma once
// The six faces of a point light's shadow map, laid out as square tiles of one 2D map: the
// layout every technique that shadows a point light in all directions shares (the frame's
// shadow_map, passes/shadow_map; esm's extended map, techniques/esm).
//
// Tiles of T = floor(map / 3) texels, three columns by two rows from the map's origin
// (+X -X +Y / -Y +Z -Z); the map's top third is unused, so a 2048^2 map holds six 682^2 faces.
// Each face's frustum is wider than 90 degrees by kFaceGuardTexels texels on every side: a
// direction belongs to the face of its major axis (light_face_of), so it lies at least that far
// inside its tile, and a bilinear footprint (or esm's quad band) around it never leaves the tile.
// Filters place each tap by its own direction (passes/common/shadow_common.glsl), so a kernel
// that crosses a face edge reads the neighbouring face where the sphere continues: no seam.
//
//   Result<PointLightFaces> f = point_light_faces(light, bounds, depth.width());
//   for (const LightFace& face : f->faces) { glViewport(face.origin.x, face.origin.y, face.size, face.size); draw(face.view_proj); }
#include <array>

#include <glm/glm.hpp>

#include "scene/light.h"
#include "scene/scene.h"
#include "util/error.h"

namespace penumbra::scene {

// Texels each face extends beyond 90 degrees on every side: a bilinear footprint (1 texel) +
// esm's silhouette quads' outer band (2 sqrt 2 texels) + margin.
inline constexpr int kFaceGuardTexels = 5;
// Smallest face (texels); the map must be at least three of these wide.
inline constexpr int kMinFaceSize = 16;

struct LightFace {
  glm::mat4 view_proj{1.0f};  // world -> clip (OpenGL convention)
  glm::ivec2 origin{0};       // tile origin in the map, texels
  int size = 0;               // tile side, texels
};

struct PointLightFaces {
  std::array<LightFace, 6> faces;  // +X, -X, +Y, -Y, +Z, -Z
  float near_plane = 0.0f;         // world units along each face's axis
  float far_plane = 1.0f;
  float tan_half_fov = 1.0f;       // of every face: T / (T - 2 kFaceGuardTexels)
  int tile = 0;                    // T, texels
};

// The faces of `light` (a point light; its `direction` is not used) for a square map of
// `map_size` texels: far is the farthest corner of `bounds` (+1 %), near 1e-3 of that.
// Errors: a map smaller than three kMinFaceSize tiles, naming both sizes.
Result<PointLightFaces> point_light_faces(const Light& light, const Bounds& bounds, int map_size);

// The face (0..5, the order above) that a direction from the light belongs to: its major axis.
// The same rule as light_face() in passes/common/light_faces.glsl.
int light_face_of(const glm::vec3& direction);

}  // namespace penumbra::scene
