#include "sspcss_rig.h"

#include <gtest/gtest.h>

#include "scene/mesh_builder.h"

namespace penumbra::test {

scene::Scene edge_test_scene() {
  scene::Scene s;
  s.name = "sspcss_edge";
  s.materials.push_back({.name = "grey", .base_color_factor = glm::vec4(0.7f, 0.7f, 0.7f, 1.0f)});
  scene::Mesh m;
  m.name = "edge";
  scene::build::add_ground(m, {0.0f, 0.0f, -1.0f}, 12.0f, 14.0f);
  // The slab: 3.5 m up over x in [0, 6], z in [-6, 3.5]: its umbra on the ground covers x > 0
  // (the light has no x component) and z < 1.4, its penumbra ~0.7 m wide (3.5 m under a sun of
  // angular diameter 2 / 10); its shadow stops short of the box.
  scene::build::add_box(m, {3.0f, 3.5f, -1.25f}, {3.0f, 0.05f, 4.75f});
  // The box near the camera, x in [-1, kBoxRight], 1.2 m high: lit (nothing above it), its own
  // shadow falls behind it (-z), over x < kBoxRight only.
  scene::build::add_box(m, {0.5f * (kBoxRight - 1.0f), 0.6f, 3.0f}, {0.5f * (kBoxRight + 1.0f), 0.6f, 0.3f});
  s.meshes.push_back(std::move(m));
  s.instances.push_back({0, glm::mat4(1.0f)});
  s.bounds = scene::compute_bounds(s);
  s.camera = scene::Camera::look_at({0.0f, 3.0f, 9.0f}, {0.6f, 0.4f, 0.0f});
  s.light.type = scene::LightType::directional;
  s.light.direction = glm::normalize(glm::vec3(0.0f, -1.0f, -0.6f));  // from above and +z
  s.light.position = s.bounds.center() - 10.0f * s.light.direction;
  s.light.size = 2.0f;
  return s;
}

}  // namespace penumbra::test
