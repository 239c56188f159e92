#pragma once
// An Embree 3 scene built from a scene::Scene: every instance flattened to world-space triangles
// (one Embree geometry per instance). Alpha-MASKED materials are respected by an intersection /
// occlusion filter that samples the base-colour texture's alpha (times the factor's alpha,
// nearest texel, repeat wrap) at the hit's interpolated UV and ignores the hit when alpha is
// below the cutoff. OPAQUE and BLEND materials block light (BLEND surfaces are treated as
// opaque casters, as the shadow-map techniques do). The RayScene copies what it needs (the
// texels' alpha included) and keeps no reference to the scene it was built from.
//
//   Result<RayScene> rs = RayScene::build(scene);
//   float t = rs->intersect(origin, dir);          // distance or +inf
#include <memory>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "util/error.h"

namespace penumbra::reference {

struct RayHit {
  float t = 0.0f;                 // distance along the (unit) direction, world units
  glm::vec3 geometric_normal{0};  // unit, world space, as Embree reports it (not flipped)
};

class RayScene {
 public:
  static Result<RayScene> build(const scene::Scene& scene);
  RayScene(RayScene&&) noexcept;
  RayScene& operator=(RayScene&&) noexcept;
  ~RayScene();

  // Closest hit along origin + t * unit_dir, t in [t_near, t_far]; false when nothing is hit.
  bool intersect(const glm::vec3& origin, const glm::vec3& unit_dir, RayHit& hit, float t_near = 0.0f,
                 float t_far = 1e30f) const;
  // Whether anything blocks origin + t * dir for t in [t_near, t_far] (dir need not be unit).
  bool occluded(const glm::vec3& origin, const glm::vec3& dir, float t_near, float t_far) const;

  const scene::Bounds& bounds() const;

 private:
  struct Impl;
  explicit RayScene(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace penumbra::reference
