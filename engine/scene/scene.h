#pragma once
// CPU-side scene data: flat, contiguous arrays that upload to GL as they are (one vertex buffer
// and one index buffer per Mesh, RGBA8 images, a world matrix per Instance) and that the Embree
// reference flattens to world-space triangles. Units: world units (metres for built-in scenes),
// Y up, right-handed (glTF convention).
//
//   Result<Scene> s = load_scene("showcase");          // or "models/Fox.gltf"
//   for (const Instance& inst : s->instances) draw(s->meshes[inst.mesh], inst.world);
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/light.h"

namespace penumbra::scene {

struct Vertex {
  glm::vec3 position{0.0f};  // object space
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // object space, unit
  glm::vec2 uv{0.0f};        // glTF convention: (0,0) = top-left of the image
};

// One glTF primitive: triangles only (3 indices per triangle, all < vertices.size()).
struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  uint32_t material = 0;  // index into Scene::materials (always valid: loaders add a default)
  size_t triangle_count() const { return indices.size() / 3; }
};

enum class AlphaMode { opaque, mask, blend };

struct Material {
  std::string name;
  glm::vec4 base_color_factor{1.0f};  // linear RGBA multiplier
  int base_color_texture = -1;        // index into Scene::images, -1 = none
  AlphaMode alpha_mode = AlphaMode::opaque;
  float alpha_cutoff = 0.5f;          // MASK: alpha < cutoff is a hole (glTF 2.0 semantics)
  bool double_sided = false;
};

// Decoded texture, always 4 channels of 8 bits, rows top to bottom.
struct Image {
  std::string name;
  int width = 0;
  int height = 0;
  std::vector<uint8_t> pixels;  // width * height * 4 bytes
};

// One placement of a mesh; the glTF node hierarchy is flattened into these.
struct Instance {
  uint32_t mesh = 0;        // index into Scene::meshes
  glm::mat4 world{1.0f};    // object -> world
};

// Axis-aligned box in world units. Default-constructed = empty (min > max).
struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{std::numeric_limits<float>::lowest()};
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  void extend(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
  void extend(const Bounds& b) { if (!b.empty()) { extend(b.min); extend(b.max); } }
  glm::vec3 center() const { return 0.5f * (min + max); }
  glm::vec3 extent() const { return max - min; }
  float radius() const { return 0.5f * glm::length(max - min); }  // of the bounding sphere
};

// A light placed by the file (glTF KHR_lights_punctual): not used for shading by itself, the
// scene's `light` stays the default; tools pick one of these to replace it.
struct SceneLight {
  std::string name;
  Light light;        // world-space position/direction from the node; size 0 (punctual)
  float range = 0.0f; // glTF range, world units; 0 = infinite
  float inner_cone_angle = 0.0f;  // spot: glTF innerConeAngle, radians (light.spot_angle is the outer)
};

// A camera a glTF file places (a node with a perspective camera): a view tools offer besides
// the fitted one (staging.h).
struct SceneCamera {
  std::string name;
  Camera camera;  // world-space, from the node; clip planes as in the file (zfar absent: 1e4 x near)
};

struct Scene {
  std::string name;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Image> images;
  std::vector<Instance> instances;
  Bounds bounds;         // world-space AABB of all instanced vertices
  Camera camera;         // default view
  Light light;           // default light
  std::vector<SceneLight> lights;  // lights placed by a glTF file (KHR_lights_punctual), in node order
  std::vector<SceneCamera> cameras;  // cameras placed by a glTF file, in node order
  std::string source_file;  // empty for built-in scenes

  // Triangles drawn (instances x mesh triangles).
  size_t triangle_count() const;
};

// World-space AABB of every instanced vertex (exact, not a transformed-box approximation).
Bounds compute_bounds(const Scene& scene);

// Scenes whose bounding sphere is outside [kMinSceneRadius, kMaxSceneRadius] world units are
// scaled uniformly to kScaledSceneRadius: float depth, bias and the fitted camera and light stop
// working far outside it (a model in 1e30 units rendered as an empty frame). Returns the factor
// applied (1 when none was needed); instances, placed lights and cameras and `bounds` follow it.
inline constexpr float kMinSceneRadius = 1e-3f, kMaxSceneRadius = 1e5f, kScaledSceneRadius = 10.0f;
float fit_scene_scale(Scene& scene);

// A camera framing `bounds` from the front-above (+Z, +Y side), whole box in view. (glTF scenes
// use framing.h's fit_camera, which fits the box rather than its bounding sphere.)
Camera frame_bounds(const Bounds& bounds, float fov_y_radians = glm::radians(50.0f));

}  // namespace penumbra::scene
