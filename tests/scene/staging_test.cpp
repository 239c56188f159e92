// Staging a scene so its shadows show: a camera fitted to the model, clip planes that let it come
// close, a light from the file or one that throws shadows towards the camera, a ground plane
// under models without a floor, and the file's own cameras. Scenes are built here or written as
// small glTF files (no external assets).
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "scene/builtin_scenes.h"
#include "scene/framing.h"
#include "scene/gltf_loader.h"
#include "scene/ground_plane.h"
#include "scene/mesh_builder.h"
#include "scene/staging.h"
#include "test_support/temp_dir.h"

using namespace penumbra;
namespace fs = std::filesystem;

namespace {

scene::Bounds box(glm::vec3 lo, glm::vec3 hi) {
  scene::Bounds b;
  b.extend(lo);
  b.extend(hi);
  return b;
}

// Normalised device coordinates of `p` seen by `cam` at `aspect`.
glm::vec3 ndc(const scene::Camera& cam, float aspect, const glm::vec3& p) {
  glm::vec4 c = cam.projection(aspect) * cam.view() * glm::vec4(p, 1.0f);
  return glm::vec3(c) / c.w;
}

// A scene of one box floating `lift` above y = 0 (no floor).
scene::Scene floating_box(float lift) {
  scene::Scene s;
  s.name = "box";
  scene::Mesh m;
  scene::build::add_box(m, {0.0f, lift + 0.5f, 0.0f}, {0.5f, 0.5f, 0.5f});
  s.meshes.push_back(m);
  s.materials.push_back({});
  s.instances.push_back({0, glm::mat4(1.0f)});
  s.bounds = scene::compute_bounds(s);
  return s;
}

// A .gltf of one upright triangle (x, y in [0, 1] at z = 0) plus `extra_nodes` and lights.
std::string write_gltf(const std::string& name, const std::string& extra_nodes, const std::string& lights,
                       const std::string& cameras) {
  std::string json = R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
  "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}}]}],)";
  if (!lights.empty())
    json += R"("extensionsUsed": ["KHR_lights_punctual"], "extensions": {"KHR_lights_punctual": {"lights": [)" + lights +
            "]}},";
  if (!cameras.empty()) json += R"("cameras": [)" + cameras + "],";
  json += R"("nodes": [{"mesh": 0})" + (extra_nodes.empty() ? "" : ", " + extra_nodes) + R"(],
  "scenes": [{"nodes": [0, 1, 2, 3]}], "scene": 0})";
  const fs::path dir = test::temp_dir("staging_test");
  const std::string path = (dir / name).string();
  std::ofstream(path) << json;
  return path;
}

// Three extra nodes so the scene's root list [0, 1, 2, 3] is always valid.
std::string nodes(const std::string& a, const std::string& b = "{}", const std::string& c = "{}") {
  return a + ", " + b + ", " + c;
}

}  // namespace

TEST(Framing, FittedCameraSeesEveryCornerAndFillsTheFrame) {
  for (float aspect : {16.0f / 9.0f, 1.0f, 0.6f}) {
    const scene::Bounds b = box({-3.0f, 0.0f, -1.0f}, {2.0f, 1.5f, 4.0f});
    const scene::Camera cam = scene::fit_camera(b, aspect);
    float widest = 0.0f;
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 c((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
      const glm::vec3 p = ndc(cam, aspect, c);
      EXPECT_LE(std::abs(p.x), 1.0f) << "aspect " << aspect << " corner " << i;
      EXPECT_LE(std::abs(p.y), 1.0f) << "aspect " << aspect << " corner " << i;
      EXPECT_GT(p.z, -1.0f);
      EXPECT_LT(p.z, 1.0f);
      widest = std::max({widest, std::abs(p.x), std::abs(p.y)});
    }
    // Tight: a corner reaches the margin (6% each side), not a bounding sphere's slack.
    EXPECT_GT(widest, 0.8f) << "aspect " << aspect;
  }
}

TEST(Framing, ClipPlanesLetTheCameraComeCloseAndBackAway) {
  const scene::Bounds b = box({-1, 0, -1}, {1, 2, 1});
  scene::Camera cam = scene::fit_camera(b, 1.5f);
  const float radius = b.radius();
  EXPECT_LT(cam.near_plane, 0.01f * radius);
  EXPECT_GT(cam.far_plane, glm::length(cam.position - b.center()) + 4.0f * radius);
}

TEST(Framing, DefaultLightThrowsShadowsTowardsTheCamera) {
  for (const glm::vec3& view : {scene::kDefaultViewDirection, glm::vec3(1, -0.3f, 0), glm::vec3(0, -0.5f, 1)}) {
    const glm::vec3 d = scene::default_light_direction(view);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
    EXPECT_LT(d.y, -0.5f) << "from above";
    // The shadow runs along the light's horizontal direction: towards the camera, to one side.
    const glm::vec2 shadow = glm::normalize(glm::vec2(d.x, d.z));
    const glm::vec2 to_camera = -glm::normalize(glm::vec2(view.x, view.z));
    EXPECT_NEAR(glm::dot(shadow, to_camera), 0.5f, 1e-4f) << "60 degrees off the line of sight";
  }
}

TEST(Ground, FloorsAreFoundAndBoxesAreNot) {
  for (const std::string& name : scene::builtin_scene_names()) {
    auto s = scene::make_builtin_scene(name);
    ASSERT_TRUE(s) << name;
    EXPECT_TRUE(scene::has_ground(*s)) << name << " has a ground";
  }
  // A box standing on y = 0: its bottom face lies there but faces down.
  EXPECT_FALSE(scene::has_ground(floating_box(0.0f)));
  EXPECT_FALSE(scene::has_ground(floating_box(2.0f)));
}

// A mat on y = 0 (10 x 10) with a piece lying beside it (x = 6..7, on y = 0): the mat covers 83%
// of the footprint but not its edge, so without a ground plane the piece would rest on nothing.
// The same piece on the mat leaves the mat a ground.
TEST(Ground, AFloorUnderOnlyPartOfTheModelIsNoGround) {
  scene::Scene s;
  s.materials.push_back({});
  scene::Mesh m;
  scene::build::add_ground(m, {0.0f, 0.0f, 0.0f}, 10.0f, 10.0f);  // x, z in -5..5
  scene::build::add_box(m, {6.5f, 0.25f, 0.0f}, {0.5f, 0.25f, 0.5f});  // beside it, on y = 0
  s.meshes.push_back(m);
  s.instances.push_back({0, glm::mat4(1.0f)});
  s.bounds = scene::compute_bounds(s);
  EXPECT_FALSE(scene::has_ground(s)) << "the piece at x = 6..7 lies beyond the mat";
  scene::Scene on_the_mat = s;
  on_the_mat.meshes[0] = scene::Mesh{};
  scene::build::add_ground(on_the_mat.meshes[0], {0.0f, 0.0f, 0.0f}, 10.0f, 10.0f);
  scene::build::add_box(on_the_mat.meshes[0], {3.5f, 0.25f, 0.0f}, {0.5f, 0.25f, 0.5f});  // on the mat
  on_the_mat.bounds = scene::compute_bounds(on_the_mat);
  EXPECT_TRUE(scene::has_ground(on_the_mat));
  s.source_file = "board.gltf";  // staged like a file: a plane goes under both
  ASSERT_TRUE(scene::stage_scene(s, {}));
  EXPECT_TRUE(scene::has_added_ground_plane(s));
}

TEST(Ground, PlaneGoesUnderTheModelAndCatchesItsShadow) {
  scene::Scene s = floating_box(1.0f);
  const scene::Bounds before = s.bounds;
  scene::add_ground_plane(s);
  EXPECT_TRUE(scene::has_added_ground_plane(s));
  EXPECT_TRUE(scene::has_ground(s));
  EXPECT_LT(s.bounds.max.y - s.bounds.min.y, before.max.y - before.min.y + 1e-3f);  // no taller
  EXPECT_LE(s.bounds.min.y, before.min.y);
  EXPECT_GT(s.bounds.min.y, before.min.y - 1e-2f);  // just below the lowest point
  // Wider than the model by at least its height on every side.
  EXPECT_LE(s.bounds.min.x, before.min.x - (before.max.y - before.min.y) + 1e-4f);
  EXPECT_GE(s.bounds.max.z, before.max.z + (before.max.y - before.min.y) - 1e-4f);
  EXPECT_EQ(scene::model_bounds(s).min.y, before.min.y);
}

TEST(Staging, GroundSwitchAndBuiltInScenesKeepTheirOwnView) {
  scene::Scene on = floating_box(0.5f), off = floating_box(0.5f);
  on.source_file = off.source_file = "box.gltf";  // staged like a file
  ASSERT_TRUE(scene::stage_scene(on, {}));
  EXPECT_TRUE(scene::has_added_ground_plane(on));
  scene::StagingOptions no_ground;
  no_ground.ground = false;
  ASSERT_TRUE(scene::stage_scene(off, no_ground));
  EXPECT_FALSE(scene::has_added_ground_plane(off));
  auto ball = scene::make_builtin_scene("ball");
  ASSERT_TRUE(ball);
  const scene::Camera cam = ball->camera;
  const scene::Light light = ball->light;
  ASSERT_TRUE(scene::stage_scene(*ball, {}));
  EXPECT_EQ(ball->camera.position, cam.position);
  EXPECT_EQ(ball->light.direction, light.direction);
  EXPECT_FALSE(scene::has_added_ground_plane(*ball));
}

TEST(Staging, TheFilesDirectionalLightIsUsed) {
  // -45 degrees about +X: the node's -Z turns to (0, -0.71, -0.71), down and away.
  const std::string path = write_gltf(
      "sun.gltf",
      nodes(R"({"rotation": [-0.3826834, 0, 0, 0.9238795], "extensions": {"KHR_lights_punctual": {"light": 0}}})"),
      R"({"type": "directional"})", "");
  auto scene = scene::load_gltf(path);
  ASSERT_TRUE(scene) << scene.error().to_string();
  ASSERT_EQ(scene->lights.size(), 1u);
  const glm::vec3 file_dir = scene->lights[0].light.direction;
  EXPECT_NEAR(file_dir.y, -std::sqrt(0.5f), 1e-5f);
  ASSERT_TRUE(scene::stage_scene(*scene, {}));
  EXPECT_EQ(scene->light.type, scene::LightType::directional);
  EXPECT_NEAR(glm::dot(scene->light.direction, file_dir), 1.0f, 1e-5f);
  EXPECT_GT(scene->light.size, 0.0f) << "a punctual light gets an emitter so shadows are soft";
  // --light-dir and --light-size still win.
  auto again = scene::load_gltf(path);
  scene::StagingOptions o;
  o.light_direction = glm::normalize(glm::vec3(1, -1, 0));
  o.light_size = 0.0f;
  ASSERT_TRUE(scene::stage_scene(*again, o));
  EXPECT_NEAR(glm::dot(again->light.direction, *o.light_direction), 1.0f, 1e-5f);
  EXPECT_EQ(again->light.size, 0.0f);
}

TEST(Staging, ADirectionForAPointLightIsAnError) {
  auto room = scene::make_builtin_scene("room");
  ASSERT_TRUE(room);
  ASSERT_EQ(room->light.type, scene::LightType::point);
  scene::StagingOptions o;
  o.light_direction = glm::vec3(0, -1, 0);
  const Status s = scene::stage_scene(*room, o);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().to_string().find("point light"), std::string::npos) << s.error().to_string();
}

TEST(Staging, WithoutALightOfItsOwnTheDefaultFollowsTheCamera) {
  auto scene = scene::load_gltf(write_gltf("plain.gltf", nodes("{}"), "", ""));
  ASSERT_TRUE(scene) << scene.error().to_string();
  ASSERT_TRUE(scene::stage_scene(*scene, {}));
  const glm::vec3 expected = scene::default_light_direction(scene->camera.forward());
  EXPECT_NEAR(glm::dot(scene->light.direction, expected), 1.0f, 1e-5f);
}

TEST(Staging, FileCamerasAreLoadedAndSelectable) {
  const std::string path = write_gltf(
      "cams.gltf", nodes(R"({"camera": 0, "translation": [0.5, 0.5, 4]})", R"({"camera": 1, "translation": [4, 0.5, 0.5],
          "rotation": [0, 0.7071068, 0, 0.7071068]})"),
      "", R"({"name": "front", "type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1, "zfar": 100}},
             {"name": "side", "type": "perspective", "perspective": {"yfov": 0.9, "znear": 0.5}})");
  auto scene = scene::load_gltf(path);
  ASSERT_TRUE(scene) << scene.error().to_string();
  ASSERT_EQ(scene->cameras.size(), 2u);
  EXPECT_EQ(scene->cameras[0].name, "front");
  EXPECT_NEAR(glm::dot(scene->cameras[0].camera.forward(), glm::vec3(0, 0, -1)), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(scene->cameras[1].camera.forward(), glm::vec3(-1, 0, 0)), 1.0f, 1e-5f) << "node -Z turned by +90 about Y";
  EXPECT_FLOAT_EQ(scene->cameras[1].camera.fov_y, 0.9f);

  scene::StagingOptions o;
  o.camera.kind = scene::CameraChoice::Kind::file;
  o.camera.file_camera = "side";
  ASSERT_TRUE(scene::stage_scene(*scene, o));
  EXPECT_EQ(scene->camera.position, glm::vec3(4, 0.5f, 0.5f));
  EXPECT_LT(scene->camera.near_plane, 0.5f) << "clip planes refitted: the camera may come close";

  auto bad = scene::load_gltf(path);
  o.camera.file_camera = "top";
  Status s = scene::stage_scene(*bad, o);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("0 'front', 1 'side'"), std::string::npos) << s.error().message;
  EXPECT_EQ(s.error().exit_code(), 2);
}

TEST(Staging, APoseLooksAtItsTarget) {
  auto scene = scene::make_builtin_scene("ball");
  ASSERT_TRUE(scene);
  scene::StagingOptions o;
  o.camera.kind = scene::CameraChoice::Kind::pose;
  o.camera.position = {3, 2, 1};
  o.camera.target = {0, 0, 0};
  ASSERT_TRUE(scene::stage_scene(*scene, o));
  EXPECT_EQ(scene->camera.position, glm::vec3(3, 2, 1));
  EXPECT_NEAR(glm::dot(scene->camera.forward(), glm::normalize(glm::vec3(-3, -2, -1))), 1.0f, 1e-5f);
}
