#pragma once
// Writes .glb files whose JSON the test states itself (extension objects, fallback buffers,
// Draco accessors without bufferViews: what tinygltf's writer cannot express), with one binary
// chunk the test appends views to.
//
//   GlbWriter w;
//   const int view = w.view(bytes.data(), bytes.size());
//   w.json["bufferViews"][view]["byteStride"] = 12;
//   w.write(dir / "m.glb");
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace penumbra::test {

struct GlbWriter {
  nlohmann::json json = {{"asset", {{"version", "2.0"}}}, {"buffers", nlohmann::json::array({nlohmann::json::object()})},
                         {"bufferViews", nlohmann::json::array()}, {"accessors", nlohmann::json::array()}};
  std::vector<uint8_t> bin;

  // Appends bytes to the binary chunk, 4-byte aligned; returns their offset.
  size_t append(const void* bytes, size_t size) {
    while (bin.size() % 4) bin.push_back(0);
    const size_t offset = bin.size();
    bin.insert(bin.end(), static_cast<const uint8_t*>(bytes), static_cast<const uint8_t*>(bytes) + size);
    return offset;
  }
  // Appends bytes as a bufferView of buffer 0.
  int view(const void* bytes, size_t size) {
    const size_t offset = append(bytes, size);
    json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}});
    return static_cast<int>(json["bufferViews"].size() - 1);
  }
  int accessor(nlohmann::json a) {
    json["accessors"].push_back(std::move(a));
    return static_cast<int>(json["accessors"].size() - 1);
  }
  // One node per mesh, all in scene 0.
  void scene_of_meshes() {
    json["scene"] = 0;
    json["scenes"] = nlohmann::json::array({{{"nodes", nlohmann::json::array()}}});
    json["nodes"] = nlohmann::json::array();
    for (size_t m = 0; m < json["meshes"].size(); ++m) {
      json["nodes"].push_back({{"mesh", m}});
      json["scenes"][0]["nodes"].push_back(m);
    }
  }
  void write(const std::filesystem::path& path) {
    while (bin.size() % 4) bin.push_back(0);
    json["buffers"][0]["byteLength"] = bin.size();
    std::string text = json.dump();
    while (text.size() % 4) text += ' ';
    std::ofstream f(path, std::ios::binary);
    auto u32 = [&](uint32_t v) { f.write(reinterpret_cast<const char*>(&v), 4); };
    f.write("glTF", 4);
    u32(2);
    u32(static_cast<uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
    u32(static_cast<uint32_t>(text.size()));
    f.write("JSON", 4);
    f.write(text.data(), static_cast<std::streamsize>(text.size()));
    u32(static_cast<uint32_t>(bin.size()));
    f.write("BIN\0", 4);
    f.write(reinterpret_cast<const char*>(bin.data()), static_cast<std::streamsize>(bin.size()));
  }
};

}  // namespace penumbra::test
