// glTF KHR_lights_punctual: the loader places every light a node refers to, with the node's
// world transform. The files are written by the test (one triangle in an embedded buffer plus
// the lights under test); no external assets.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include "scene/gltf_loader.h"
#include "test_support/temp_dir.h"

using namespace penumbra;
namespace fs = std::filesystem;

namespace {

// A .gltf whose scene has the triangle node 0 and then `nodes` (JSON objects, comma-separated,
// indices 1...), `lights` as the KHR_lights_punctual array.
std::string write_gltf(const std::string& name, const std::string& nodes, const std::string& lights,
                       const std::string& roots) {
  const std::string json = R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [)" + lights + R"(]}},
  "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
  "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}}]}],
  "nodes": [{"mesh": 0})" + (nodes.empty() ? "" : ", " + nodes) + R"(],
  "scenes": [{"nodes": [0)" + (roots.empty() ? "" : ", " + roots) + R"(]}],
  "scene": 0
})";
  const fs::path dir = test::temp_dir("gltf_lights_test");
  const std::string path = (dir / name).string();
  std::ofstream(path) << json;
  return path;
}

void expect_vec3(const glm::vec3& a, const glm::vec3& b, const char* what) {
  EXPECT_NEAR(a.x, b.x, 1e-5f) << what;
  EXPECT_NEAR(a.y, b.y, 1e-5f) << what;
  EXPECT_NEAR(a.z, b.z, 1e-5f) << what;
}

}  // namespace

TEST(GltfLights, AllThreeTypesArePlacedByTheirNodes) {
  const float s = std::sqrt(0.5f);  // quaternion (x, y, z, w) of 90 degrees about +X: -Z -> -Y (down)
  const std::string path = write_gltf(
      "three.gltf",
      R"({"name": "sun", "rotation": [)" + std::to_string(-s) + ", 0, 0, " + std::to_string(s) +
          R"(], "extensions": {"KHR_lights_punctual": {"light": 0}}},
         {"name": "lamp", "translation": [1, 2, 3], "extensions": {"KHR_lights_punctual": {"light": 1}}},
         {"name": "bulb", "translation": [0, 5, 0], "extensions": {"KHR_lights_punctual": {"light": 2}}})",
      R"({"name": "sunlight", "type": "directional", "color": [1, 0.9, 0.8], "intensity": 3},
         {"name": "spot", "type": "spot", "intensity": 40, "range": 12,
          "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}},
         {"name": "bulb", "type": "point", "intensity": 15})",
      "1, 2, 3");
  Result<scene::Scene> r = scene::load_gltf(path);
  ASSERT_TRUE(r) << r.error().to_string();
  ASSERT_EQ(r->lights.size(), 3u);
  const scene::SceneLight& sun = r->lights[0];
  EXPECT_EQ(sun.name, "sunlight");
  EXPECT_EQ(sun.light.type, scene::LightType::directional);
  expect_vec3(sun.light.direction, {0, -1, 0}, "sun direction: -Z rotated -90 degrees about X");
  expect_vec3(sun.light.color, {1, 0.9f, 0.8f}, "sun colour");
  EXPECT_FLOAT_EQ(sun.light.intensity, 3.0f);
  const scene::SceneLight& spot = r->lights[1];
  EXPECT_EQ(spot.light.type, scene::LightType::spot);
  expect_vec3(spot.light.position, {1, 2, 3}, "spot position");
  expect_vec3(spot.light.direction, {0, 0, -1}, "spot direction: the node's -Z");
  EXPECT_FLOAT_EQ(spot.light.spot_angle, 0.6f);
  EXPECT_FLOAT_EQ(spot.inner_cone_angle, 0.2f);
  EXPECT_FLOAT_EQ(spot.range, 12.0f);
  EXPECT_FLOAT_EQ(spot.light.intensity, 40.0f);
  const scene::SceneLight& bulb = r->lights[2];
  EXPECT_EQ(bulb.light.type, scene::LightType::point);
  expect_vec3(bulb.light.position, {0, 5, 0}, "point position");
  EXPECT_EQ(bulb.range, 0.0f);  // absent = infinite
  for (const scene::SceneLight& l : r->lights) EXPECT_EQ(l.light.size, 0.0f) << l.name << " is punctual";
  // The scene's own light stays the default one: a file's lights are there to be picked.
  EXPECT_EQ(r->light.type, scene::LightType::directional);
}

TEST(GltfLights, ChildNodesComposeTheirParentsTransforms) {
  const std::string path = write_gltf(
      "child.gltf",
      R"({"translation": [10, 0, 0], "scale": [2, 2, 2], "children": [2]},
         {"translation": [0, 1, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}})",
      R"({"type": "point"})", "1");
  Result<scene::Scene> r = scene::load_gltf(path);
  ASSERT_TRUE(r) << r.error().to_string();
  ASSERT_EQ(r->lights.size(), 1u);
  expect_vec3(r->lights[0].light.position, {10, 2, 0}, "parent translation + scaled child translation");
}

TEST(GltfLights, AFileWithoutLightsHasNone) {
  const std::string path = write_gltf("none.gltf", "", "", "");
  Result<scene::Scene> r = scene::load_gltf(path);
  ASSERT_TRUE(r) << r.error().to_string();
  EXPECT_TRUE(r->lights.empty());
}

struct BadLights {
  const char* name;
  std::string nodes, lights;
  const char* must_contain;
};

class GltfLightErrors : public ::testing::TestWithParam<BadLights> {};

TEST_P(GltfLightErrors, AreBadInputNamingTheNode) {
  const BadLights& b = GetParam();
  Result<scene::Scene> r = scene::load_gltf(write_gltf(std::string(b.name) + ".gltf", b.nodes, b.lights, "1"));
  ASSERT_FALSE(r);
  const std::string msg = r.error().to_string();
  EXPECT_NE(msg.find(b.must_contain), std::string::npos) << msg;
  EXPECT_EQ(r.error().exit_code(), 2);
}

INSTANTIATE_TEST_SUITE_P(
    Gltf, GltfLightErrors,
    ::testing::Values(
        BadLights{"index", R"({"name": "lamp", "extensions": {"KHR_lights_punctual": {"light": 4}}})",
                  R"({"type": "point"})", "light index 4 does not exist"},
        BadLights{"type", R"({"name": "lamp", "extensions": {"KHR_lights_punctual": {"light": 0}}})",
                  R"({"type": "area"})", "has type 'area'; expected directional, spot or point"},
        BadLights{"noref", R"({"name": "lamp", "extensions": {"KHR_lights_punctual": {}}})",
                  R"({"type": "point"})", "node 1 'lamp'"},
        BadLights{"spot", R"({"extensions": {"KHR_lights_punctual": {"light": 0}}})",
                  R"({"type": "spot"})", "invalid or truncated"}),
    [](const auto& info) { return std::string(info.param.name); });
