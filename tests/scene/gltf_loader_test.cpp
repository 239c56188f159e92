// The loader on glTF files the test writes itself with tinygltf (no external assets).
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "scene/gltf_loader.h"
#include "test_support/temp_dir.h"

using namespace penumbra;
namespace fs = std::filesystem;

namespace {

// Builds a Model with one buffer; every accessor gets its own bufferView.
struct ModelBuilder {
  tinygltf::Model model;
  ModelBuilder() {
    model.buffers.emplace_back();
    model.buffers[0].uri = "data.bin";
    model.asset.version = "2.0";
  }
  int accessor(const void* bytes, size_t size, int component_type, int type, size_t count) {
    auto& data = model.buffers[0].data;
    while (data.size() % 4) data.push_back(0);
    tinygltf::BufferView bv;
    bv.buffer = 0;
    bv.byteOffset = data.size();
    bv.byteLength = size;
    data.insert(data.end(), static_cast<const uint8_t*>(bytes), static_cast<const uint8_t*>(bytes) + size);
    model.bufferViews.push_back(bv);
    tinygltf::Accessor acc;
    acc.bufferView = static_cast<int>(model.bufferViews.size() - 1);
    acc.componentType = component_type;
    acc.type = type;
    acc.count = count;
    if (type == TINYGLTF_TYPE_VEC3 && component_type == TINYGLTF_COMPONENT_TYPE_FLOAT) {  // min/max required
      const float* f = static_cast<const float*>(bytes);
      acc.minValues = {1e30, 1e30, 1e30};
      acc.maxValues = {-1e30, -1e30, -1e30};
      for (size_t i = 0; i < count * 3; ++i) {
        acc.minValues[i % 3] = std::min(acc.minValues[i % 3], static_cast<double>(f[i]));
        acc.maxValues[i % 3] = std::max(acc.maxValues[i % 3], static_cast<double>(f[i]));
      }
    }
    model.accessors.push_back(acc);
    return static_cast<int>(model.accessors.size() - 1);
  }
  // A unit quad in XY (z = 0), with UVs and u16 indices; returns the mesh index.
  int quad(int mode = TINYGLTF_MODE_TRIANGLES, uint16_t bad_index = 0, int material = -1) {
    const float pos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const float uv[] = {0, 1, 1, 1, 1, 0, 0, 0};
    const uint16_t idx[] = {0, 1, 2, 0, 2, static_cast<uint16_t>(bad_index ? bad_index : 3)};
    tinygltf::Primitive p;
    p.attributes["POSITION"] = accessor(pos, sizeof pos, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 4);
    p.attributes["TEXCOORD_0"] = accessor(uv, sizeof uv, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, 4);
    p.indices = accessor(idx, sizeof idx, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, 6);
    p.mode = mode;
    p.material = material;
    tinygltf::Mesh m;
    m.name = "quad";
    m.primitives.push_back(p);
    model.meshes.push_back(m);
    return static_cast<int>(model.meshes.size() - 1);
  }
  int node(int mesh, std::vector<int> children = {}) {
    tinygltf::Node n;
    n.mesh = mesh;
    n.children = std::move(children);
    model.nodes.push_back(n);
    return static_cast<int>(model.nodes.size() - 1);
  }
  void scene(std::vector<int> roots) {
    tinygltf::Scene s;
    s.nodes = std::move(roots);
    model.scenes.push_back(s);
    model.defaultScene = 0;
  }
  std::string write(const std::string& name, bool binary = false) {
    const fs::path dir = test::temp_dir("gltf_test");
    model.buffers[0].uri = fs::path(name).stem().string() + ".bin";
    const std::string path = (dir / name).string();
    tinygltf::TinyGLTF io;
    EXPECT_TRUE(io.WriteGltfSceneToFile(&model, path, true, binary, false, binary)) << path;
    return path;
  }
};

std::string error_of(const std::string& path) {
  Result<scene::Scene> s = scene::load_gltf(path);
  EXPECT_FALSE(s) << path << " loaded but should not";
  if (s) return {};
  EXPECT_EQ(s.error().file, path);
  return s.error().to_string();
}

}  // namespace

TEST(GltfLoader, NodeHierarchyComposesChildWithParent) {
  ModelBuilder b;
  const int mesh = b.quad();
  const int child = b.node(mesh);
  b.model.nodes[static_cast<size_t>(child)].translation = {0, 0, 5};
  b.model.nodes[static_cast<size_t>(child)].scale = {2, 2, 2};
  const int parent = b.node(-1, {child});
  b.model.nodes[static_cast<size_t>(parent)].translation = {10, 0, 0};
  b.model.nodes[static_cast<size_t>(parent)].rotation = {0, 0.7071068, 0, 0.7071068};  // 90 deg about +Y
  b.scene({parent});
  const std::string path = b.write("hierarchy.gltf");
  Result<scene::Scene> s = scene::load_gltf(path);
  ASSERT_TRUE(s) << s.error().to_string();
  ASSERT_EQ(s->instances.size(), 1u);
  EXPECT_EQ(s->triangle_count(), 2u);
  // Child origin (0,0,5) rotated 90 deg about Y -> (5,0,0), then + (10,0,0).
  const glm::vec4 origin = s->instances[0].world * glm::vec4(0, 0, 0, 1);
  EXPECT_NEAR(origin.x, 15.0f, 1e-4f);
  EXPECT_NEAR(origin.z, 0.0f, 1e-4f);
  // Vertex (1,0,0) scaled by 2 then rotated: (0,0,-2) relative to the child origin.
  const glm::vec4 corner = s->instances[0].world * glm::vec4(1, 0, 0, 1);
  EXPECT_NEAR(corner.x, 15.0f, 1e-4f);
  EXPECT_NEAR(corner.z, -2.0f, 1e-4f);
  EXPECT_NEAR(s->bounds.max.y - s->bounds.min.y, 2.0f, 1e-4f);
  // No NORMAL attribute: flat normals generated, facing +Z in object space.
  for (const scene::Vertex& v : s->meshes[0].vertices) EXPECT_NEAR(v.normal.z, 1.0f, 1e-5f);
}

TEST(GltfLoader, AlphaMaskedTexturedQuadAsGlb) {
  ModelBuilder b;
  tinygltf::Image img;
  img.width = 2, img.height = 2, img.component = 4, img.bits = 8;
  img.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  img.mimeType = "image/png";
  img.image = {255, 0, 0, 255, 0, 255, 0, 0, 0, 0, 255, 255, 255, 255, 255, 10};
  b.model.images.push_back(img);
  tinygltf::Texture tex;
  tex.source = 0;
  b.model.textures.push_back(tex);
  tinygltf::Material mat;
  mat.alphaMode = "MASK";
  mat.alphaCutoff = 0.3;
  mat.doubleSided = true;
  mat.pbrMetallicRoughness.baseColorTexture.index = 0;
  mat.pbrMetallicRoughness.baseColorFactor = {1, 0.5, 1, 1};
  b.model.materials.push_back(mat);
  b.scene({b.node(b.quad(TINYGLTF_MODE_TRIANGLES, 0, 0))});
  const std::string path = b.write("masked.glb", true);
  Result<scene::Scene> s = scene::load_gltf(path);
  ASSERT_TRUE(s) << s.error().to_string();
  ASSERT_EQ(s->images.size(), 1u);
  EXPECT_EQ(s->images[0].width, 2);
  EXPECT_EQ(s->images[0].pixels, img.image);
  const scene::Material& m = s->materials[s->meshes[0].material];
  EXPECT_EQ(m.alpha_mode, scene::AlphaMode::mask);
  EXPECT_FLOAT_EQ(m.alpha_cutoff, 0.3f);
  EXPECT_TRUE(m.double_sided);
  EXPECT_EQ(m.base_color_texture, 0);
  EXPECT_FLOAT_EQ(m.base_color_factor.g, 0.5f);
  EXPECT_NEAR(s->meshes[0].vertices[0].uv.y, 1.0f, 1e-6f);
}

TEST(GltfLoader, RejectsMissingFile) {
  const std::string msg = error_of("/nonexistent/dir/model.gltf");
  EXPECT_NE(msg.find("not found"), std::string::npos) << msg;
}

// A .gltf name that leads to a device that never ends (here a link to /dev/zero) is refused
// before a byte is read, not read until memory runs out.
TEST(GltfLoader, RejectsADeviceBehindAGltfName) {
  const fs::path link = fs::temp_directory_path() / ("penumbra_zero_" + std::to_string(::getpid()) + ".gltf");
  fs::remove(link);
  fs::create_symlink("/dev/zero", link);
  const std::string msg = error_of(link.string());
  EXPECT_NE(msg.find("is a character device, not a regular file"), std::string::npos) << msg;
  fs::remove(link);
}

// A .glb whose JSON chunk nests past the one limit is refused before tinygltf's parser recurses.
TEST(GltfLoader, RejectsDeepNestingInAGlbsJsonChunk) {
  std::string json = "{\"asset\": {\"version\": \"2.0\", \"extras\": " + std::string(5000, '[') +
                     std::string(5000, ']') + "}}";
  while (json.size() % 4) json += ' ';
  std::string glb = "glTF";
  auto put32 = [&](uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  put32(2);
  put32(static_cast<uint32_t>(12 + 8 + json.size()));
  put32(static_cast<uint32_t>(json.size()));
  glb += "JSON" + json;
  const fs::path path = fs::temp_directory_path() / ("penumbra_deep_" + std::to_string(::getpid()) + ".glb");
  std::ofstream(path, std::ios::binary) << glb;
  const std::string msg = error_of(path.string());
  EXPECT_NE(msg.find("nesting deeper than 64"), std::string::npos) << msg;
  fs::remove(path);
}

TEST(GltfLoader, RejectsTruncatedGlb) {
  ModelBuilder b;
  b.scene({b.node(b.quad())});
  const std::string path = b.write("truncated.glb", true);
  fs::resize_file(path, fs::file_size(path) / 2);
  const std::string msg = error_of(path);
  EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
  EXPECT_NE(msg.find("truncated.glb"), std::string::npos) << msg;
}

TEST(GltfLoader, RejectsMissingBufferFile) {
  ModelBuilder b;
  b.scene({b.node(b.quad())});
  const std::string path = b.write("nobuffer.gltf");
  fs::remove(fs::path(path).parent_path() / "nobuffer.bin");
  const std::string msg = error_of(path);
  EXPECT_NE(msg.find("nobuffer.bin"), std::string::npos) << msg;
}

TEST(GltfLoader, RejectsOutOfRangeIndices) {
  ModelBuilder b;
  b.scene({b.node(b.quad(TINYGLTF_MODE_TRIANGLES, 99))});
  const std::string path = b.write("badindex.gltf");
  const std::string msg = error_of(path);
  EXPECT_NE(msg.find("index 99"), std::string::npos) << msg;
  EXPECT_NE(msg.find("out of range"), std::string::npos) << msg;
  EXPECT_NE(msg.find("mesh 0"), std::string::npos) << msg;
}

TEST(GltfLoader, RejectsAccessorPastItsBuffer) {
  ModelBuilder b;
  b.scene({b.node(b.quad())});
  b.model.accessors[0].count = 1000000;  // POSITION claims far more data than exists
  const std::string path = b.write("overrun.gltf");
  Result<scene::Scene> s = scene::load_gltf(path);
  ASSERT_FALSE(s);  // either tinygltf or our own bounds check must refuse it, without crashing
  EXPECT_EQ(s.error().file, path);
}

TEST(GltfLoader, RejectsLinesNamingTheMode) {
  ModelBuilder b;
  b.scene({b.node(b.quad(TINYGLTF_MODE_LINE))});
  const std::string path = b.write("lines.gltf");
  const std::string msg = error_of(path);
  EXPECT_NE(msg.find("LINES"), std::string::npos) << msg;
  EXPECT_NE(msg.find("only TRIANGLES"), std::string::npos) << msg;
}

TEST(GltfLoader, RejectsFileWithoutMeshes) {
  ModelBuilder b;
  b.model.buffers.clear();
  b.model.buffers.emplace_back();
  b.model.buffers[0].data = {0, 0, 0, 0};
  b.scene({b.node(-1)});
  b.model.nodes[0].name = "empty";  // an all-default node would be written as null
  const std::string path = b.write("empty.gltf");
  const std::string msg = error_of(path);
  EXPECT_NE(msg.find("no meshes"), std::string::npos) << msg;
}
