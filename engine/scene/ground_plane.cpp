#include "scene/ground_plane.h"

#include <algorithm>
#include <cmath>

#include "scene/mesh_builder.h"

namespace penumbra::scene {

bool has_ground(const Scene& scene) {
  const Bounds& b = scene.bounds;
  if (b.empty()) return false;
  const glm::vec3 extent = b.extent();
  const double footprint = double(extent.x) * double(extent.z);
  if (!(footprint > 0.0)) return false;
  // "At the bottom": within 2% of the larger of height and width above the lowest point.
  const float slab = 0.02f * std::max({extent.x, extent.y, extent.z});
  double floor_area = 0.0;
  Bounds floor;  // of the floor triangles
  for (const Instance& inst : scene.instances) {
    if (inst.mesh >= scene.meshes.size()) continue;
    const Mesh& mesh = scene.meshes[inst.mesh];
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(inst.world)));
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      glm::vec3 p[3], n_sum(0.0f);
      bool low = true;
      for (int k = 0; k < 3; ++k) {
        const Vertex& v = mesh.vertices[mesh.indices[t + k]];
        p[k] = glm::vec3(inst.world * glm::vec4(v.position, 1.0f));
        n_sum += normal_matrix * v.normal;
        low = low && p[k].y <= b.min.y + slab;
      }
      if (!low) continue;
      glm::vec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
      const float twice_area = glm::length(face);
      if (!(twice_area > 0.0f)) continue;
      face /= twice_area;
      if (glm::dot(face, n_sum) < 0.0f) face = -face;  // the side the surface faces
      if (face.y > 0.9f) {
        floor_area += 0.5 * double(twice_area) * double(face.y);  // area seen from above
        for (const glm::vec3& q : p) floor.extend(q);
      }
    }
  }
  // A floor under part of the model (a board with pieces lying beside it) leaves the rest resting
  // on nothing: the floor must reach the model's footprint on every side.
  const bool under_everything = !floor.empty() && floor.min.x <= b.min.x + slab && floor.max.x >= b.max.x - slab &&
                                floor.min.z <= b.min.z + slab && floor.max.z >= b.max.z - slab;
  return under_everything && floor_area >= kGroundCoverage * footprint;
}

size_t add_ground_plane(Scene& scene) {
  const Bounds b = scene.bounds.empty() ? Bounds{glm::vec3(-1.0f), glm::vec3(1.0f)} : scene.bounds;
  const glm::vec3 extent = b.extent();
  const float half = std::max(extent.x, extent.z) * 0.5f + std::max(extent.y, 1e-3f);
  // Just below the lowest point: coplanar with a flat bottom it would fight it for depth.
  const float y = b.min.y - 1e-4f * std::max({extent.x, extent.y, extent.z, 1e-3f});
  Mesh mesh;
  mesh.name = std::string(kGroundPlaneName);
  build::add_ground(mesh, glm::vec3(b.center().x, y, b.center().z), 2.0f * half, 2.0f * half);
  mesh.material = static_cast<uint32_t>(scene.materials.size());
  scene.materials.push_back(Material{.name = std::string(kGroundPlaneName), .base_color_factor = glm::vec4(0.62f, 0.62f, 0.6f, 1.0f)});
  const size_t index = scene.meshes.size();
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back({static_cast<uint32_t>(index), glm::mat4(1.0f)});
  scene.bounds = compute_bounds(scene);
  return index;
}

bool has_added_ground_plane(const Scene& scene) {
  return std::any_of(scene.meshes.begin(), scene.meshes.end(),
                     [](const Mesh& m) { return m.name == kGroundPlaneName; });
}

}  // namespace penumbra::scene
