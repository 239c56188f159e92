#pragma once
// A small glTF the sandbox tests write for themselves (never a shared asset): one box floating
// above y = 0 with no floor, optionally with a KHR_lights_punctual directional light whose node
// turns -Z to a given direction. Positions only (the loader makes flat normals).
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace penumbra::sandbox_test {

struct Vec3 {
  float x, y, z;
};

// The 12 outward-facing triangles of the box [lo, hi], 36 positions.
inline std::vector<float> box_triangles(Vec3 lo, Vec3 hi) {
  const std::array<Vec3, 8> c = {{{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                                  {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}}};
  // Each face as a quad, counter-clockwise seen from outside.
  const int quads[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
  std::vector<float> out;
  for (const auto& q : quads)
    for (int i : {q[0], q[1], q[2], q[0], q[2], q[3]}) out.insert(out.end(), {c[i].x, c[i].y, c[i].z});
  return out;
}

// The unit quaternion (x, y, z, w) turning (0, 0, -1) onto `dir` (normalised here).
inline std::array<float, 4> rotation_from_minus_z(Vec3 dir) {
  const float len = std::sqrt(dir.x * dir.x + dir.y * dir.y + dir.z * dir.z);
  const Vec3 b{dir.x / len, dir.y / len, dir.z / len};
  // q = (a x b, 1 + a.b) normalised, a = (0, 0, -1).
  std::array<float, 4> q = {b.y, -b.x, 0.0f, 1.0f - b.z};
  const float n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (float& v : q) v /= n;
  return q;
}

// Writes dir/name.gltf + dir/name.bin: a 1 x 1 x 1 box floating at y in [1, 2] over the origin;
// with `light_direction` a directional light shining that way. Returns the .gltf path.
inline std::string write_floating_box(const std::filesystem::path& dir, const std::string& name,
                                      const Vec3* light_direction = nullptr) {
  const std::vector<float> p = box_triangles({-0.5f, 1.0f, -0.5f}, {0.5f, 2.0f, 0.5f});
  const size_t bytes = p.size() * sizeof(float);
  std::ofstream(dir / (name + ".bin"), std::ios::binary).write(reinterpret_cast<const char*>(p.data()), bytes);
  std::string json = R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": )" + std::to_string(bytes) + R"(, "uri": ")" + name + R"(.bin"}],
  "bufferViews": [{"buffer": 0, "byteLength": )" + std::to_string(bytes) + R"(}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 36, "type": "VEC3",
                 "min": [-0.5, 1, -0.5], "max": [0.5, 2, 0.5]}],
  "meshes": [{"name": "box", "primitives": [{"attributes": {"POSITION": 0}}]}],)";
  std::string nodes = R"({"mesh": 0})";
  if (light_direction) {
    const auto q = rotation_from_minus_z(*light_direction);
    json += R"("extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "name": "sun"}]}},)";
    nodes += R"(, {"rotation": [)" + std::to_string(q[0]) + ", " + std::to_string(q[1]) + ", " +
             std::to_string(q[2]) + ", " + std::to_string(q[3]) +
             R"(], "extensions": {"KHR_lights_punctual": {"light": 0}}})";
  }
  json += R"("nodes": [)" + nodes + R"(], "scenes": [{"nodes": [0)" + std::string(light_direction ? ", 1" : "") +
          R"(]}], "scene": 0})";
  const std::filesystem::path path = dir / (name + ".gltf");
  std::ofstream(path) << json;
  return path.string();
}

}  // namespace penumbra::sandbox_test
