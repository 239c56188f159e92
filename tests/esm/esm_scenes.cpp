#include "esm_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include "scene/mesh_builder.h"

namespace penumbra::test {
namespace {

uint32_t material(scene::Scene& s, const glm::vec3& colour) {
  s.materials.push_back({.base_color_factor = glm::vec4(colour, 1.0f)});
  return static_cast<uint32_t>(s.materials.size() - 1);
}

void add(scene::Scene& s, scene::Mesh m, uint32_t mat) {
  m.material = mat;
  s.meshes.push_back(std::move(m));
  s.instances.push_back({static_cast<uint32_t>(s.meshes.size() - 1), glm::mat4(1.0f)});
}

scene::Mesh inside_box(const glm::vec3& half) {
  scene::Mesh m;
  m.name = "room";
  scene::build::add_inside_box(m, glm::vec3(0.0f), half);
  return m;
}

}  // namespace

scene::Camera view(const glm::vec3& eye, const glm::vec3& target, float fov_deg) {
  return scene::Camera::look_at(eye, target, glm::radians(fov_deg), 0.02f, 50.0f);
}

scene::Scene point_lit_room(const glm::vec3& light) {
  scene::Scene s;
  s.name = "point_room";
  add(s, inside_box(glm::vec3(4.0f)), material(s, glm::vec3(0.75f)));
  scene::Mesh rods;
  rods.name = "rods";
  const glm::vec3& l = light;
  // Rods along each axis, offset from the light, long enough to shadow across face boundaries.
  scene::build::add_cylinder(rods, l + glm::vec3(-2.5f, 0.9f, 0.6f), l + glm::vec3(2.5f, 0.9f, 0.6f), 0.08f, 16);
  scene::build::add_cylinder(rods, l + glm::vec3(0.7f, -2.5f, -0.8f), l + glm::vec3(0.7f, 2.5f, -0.8f), 0.08f, 16);
  scene::build::add_cylinder(rods, l + glm::vec3(-0.9f, -0.6f, -2.5f), l + glm::vec3(-0.9f, -0.6f, 2.5f), 0.08f, 16);
  add(s, std::move(rods), material(s, glm::vec3(0.4f, 0.5f, 0.8f)));
  scene::Mesh ball;
  ball.name = "ball";
  scene::build::add_sphere(ball, l + glm::vec3(1.0f, 1.0f, 1.0f), 0.35f, 32, 16);  // on the +x+y+z diagonal
  add(s, std::move(ball), material(s, glm::vec3(0.8f, 0.3f, 0.2f)));
  s.bounds = scene::compute_bounds(s);
  s.light.type = scene::LightType::point;
  s.light.position = light;
  s.light.size = 0.0f;
  s.light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  s.camera = view(light, light + glm::vec3(0, 0, -1), 90.0f);
  return s;
}

scene::Scene crossed_pipes(float radius, float gap) {
  scene::Scene s;
  s.name = "crossed_pipes";
  scene::Mesh wall;
  wall.name = "wall";
  scene::build::add_ground(wall, {0, 0, 0}, 6.0f, 6.0f);
  for (scene::Vertex& v : wall.vertices) {  // the XZ ground turned into the XY plane, facing +z
    v.position = glm::vec3(v.position.x, -v.position.z, 0.0f);
    v.normal = glm::vec3(0, 0, 1);
  }
  add(s, std::move(wall), material(s, glm::vec3(0.75f)));
  scene::Mesh pipes;
  pipes.name = "pipes";
  scene::build::add_cylinder(pipes, {-2.2f, 0.1f, 1.0f}, {2.2f, -0.1f, 1.0f}, radius, 24);           // nearly horizontal
  scene::build::add_cylinder(pipes, {-0.1f, -2.2f, 1.0f + gap}, {0.1f, 2.2f, 1.0f + gap}, radius, 24);  // nearly vertical
  add(s, std::move(pipes), material(s, glm::vec3(0.4f, 0.5f, 0.8f)));
  s.bounds = scene::compute_bounds(s);
  s.light.type = scene::LightType::spot;
  s.light.position = {0.9f, 1.3f, 6.0f};
  s.light.direction = glm::normalize(glm::vec3(0.0f, 0.0f, 0.0f) - s.light.position);
  s.light.spot_angle = glm::radians(35.0f);
  s.light.size = 0.0f;
  s.camera = view({-0.6f, -0.4f, 4.5f}, {0.0f, 0.0f, 0.0f}, 45.0f);
  return s;
}

scene::Scene plates_and_sheet(float thickness, const glm::vec3& light) {
  scene::Scene s;
  s.name = "plates_and_sheet";
  scene::Mesh ground;
  ground.name = "ground";
  scene::build::add_ground(ground, {0, 0, 0}, 8.0f, 8.0f);
  add(s, std::move(ground), material(s, glm::vec3(0.75f)));
  scene::Mesh plates;
  plates.name = "plates";
  const glm::vec3 half(0.35f, 0.5f * thickness, 0.15f);
  const float turns[] = {0.0f, 25.0f, 60.0f, 110.0f};
  const glm::vec2 places[] = {{-0.45f, 0.45f}, {0.45f, 0.45f}, {-0.45f, -0.3f}, {0.45f, -0.3f}};
  for (int i = 0; i < 4; ++i) {
    const glm::mat3 turn(glm::rotate(glm::mat4(1.0f), glm::radians(turns[i]), glm::vec3(0, 1, 0)));
    scene::build::add_box(plates, {places[i].x, 0.5f * thickness, places[i].y}, half, turn);
  }
  add(s, std::move(plates), material(s, glm::vec3(0.4f, 0.5f, 0.8f)));
  scene::Mesh sheet;
  sheet.name = "sheet";
  scene::build::add_ground(sheet, {0, 0, 0}, 0.6f, 0.5f);
  // Rising by 25 degrees towards the light's side (+x), where its rim is nearest the light.
  const glm::mat4 place = glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 0.45f, -1.0f)) *
                          glm::rotate(glm::mat4(1.0f), glm::radians(25.0f), glm::vec3(0, 0, 1));
  for (scene::Vertex& v : sheet.vertices) {
    v.position = glm::vec3(place * glm::vec4(v.position, 1.0f));
    v.normal = glm::normalize(glm::mat3(place) * v.normal);
  }
  add(s, std::move(sheet), material(s, glm::vec3(0.8f, 0.6f, 0.3f)));
  s.bounds = scene::compute_bounds(s);
  s.light.type = scene::LightType::spot;
  s.light.position = light;
  s.light.direction = glm::normalize(glm::vec3(0.0f, 0.0f, -0.3f) - s.light.position);
  s.light.spot_angle = glm::radians(35.0f);
  s.light.size = 0.0f;
  s.camera = view({-0.15f, 1.0f, 1.2f}, {0.0f, 0.0f, -0.25f}, 50.0f);
  return s;
}

}  // namespace penumbra::test
