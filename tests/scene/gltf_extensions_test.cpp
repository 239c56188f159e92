// The glTF extensions the loader decodes, each on a file the test writes itself: a compressed or
// quantized file against its plain twin (same triangles within the quantization error, same
// ray-traced shadow mask), texture transforms against the extension's matrix, and damaged
// streams and values refused with the mesh, primitive and extension named.
#include <algorithm>
#include <cmath>
#include <functional>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include "glb_writer.h"
#include "raytraced_reference.h"
#include "scene/gltf_extension_data.h"
#include "scene/gltf_extension_table.h"
#include "scene/gltf_loader.h"
#include "scene/mesh_builder.h"
#include "test_support/temp_dir.h"
#include "util/png.h"

using namespace penumbra;
namespace fs = std::filesystem;
using nlohmann::json;
using test::GlbWriter;

namespace {

// A caster with curved and flat faces: a sphere beside a box, about 2 units across.
scene::Mesh caster() {
  scene::Mesh m;
  scene::build::add_sphere(m, {0.0f, 1.0f, 0.0f}, 0.5f, 12, 6);
  scene::build::add_box(m, {0.8f, 0.4f, 0.2f}, {0.2f, 0.4f, 0.3f});
  return m;
}

json vec3_bounds(const std::vector<scene::Vertex>& v, const char* key) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const scene::Vertex& x : v) lo = glm::min(lo, x.position), hi = glm::max(hi, x.position);
  return key == std::string("min") ? json{lo.x, lo.y, lo.z} : json{hi.x, hi.y, hi.z};
}

// The plain twin: float positions, normals and UVs, 32-bit indices.
void add_plain_mesh(GlbWriter& w, const scene::Mesh& m) {
  std::vector<float> pos, nrm, uv;
  for (const scene::Vertex& v : m.vertices) {
    pos.insert(pos.end(), {v.position.x, v.position.y, v.position.z});
    nrm.insert(nrm.end(), {v.normal.x, v.normal.y, v.normal.z});
    uv.insert(uv.end(), {v.uv.x, v.uv.y});
  }
  const size_t n = m.vertices.size();
  json prim = {{"attributes",
                {{"POSITION", w.accessor({{"bufferView", w.view(pos.data(), pos.size() * 4)}, {"componentType", 5126},
                                          {"count", n}, {"type", "VEC3"}, {"min", vec3_bounds(m.vertices, "min")},
                                          {"max", vec3_bounds(m.vertices, "max")}})},
                 {"NORMAL", w.accessor({{"bufferView", w.view(nrm.data(), nrm.size() * 4)}, {"componentType", 5126},
                                        {"count", n}, {"type", "VEC3"}})},
                 {"TEXCOORD_0", w.accessor({{"bufferView", w.view(uv.data(), uv.size() * 4)}, {"componentType", 5126},
                                            {"count", n}, {"type", "VEC2"}})}}},
               {"indices", w.accessor({{"bufferView", w.view(m.indices.data(), m.indices.size() * 4)},
                                       {"componentType", 5125}, {"count", m.indices.size()}, {"type", "SCALAR"}})}};
  w.json["meshes"].push_back({{"primitives", json::array({prim})}});
}

// The mesh uncompressed, alone in a .glb: the twin a compressed file is compared with.
void write_plain_twin(const scene::Mesh& m, const fs::path& file) {
  GlbWriter plain;
  add_plain_mesh(plain, m);
  plain.scene_of_meshes();
  plain.write(file);
}

// The Draco twin (KHR_draco_mesh_compression), sequential encoding so the triangles keep their
// order; positions quantized to `position_bits`.
std::vector<uint8_t> draco_stream(const scene::Mesh& m, int position_bits, int ids[3]) {
  draco::Mesh dm;
  const auto n = static_cast<uint32_t>(m.vertices.size());
  dm.set_num_points(n);
  auto add = [&](draco::GeometryAttribute::Type type, int components, auto value_of) {
    draco::GeometryAttribute ga;
    ga.Init(type, nullptr, static_cast<int8_t>(components), draco::DT_FLOAT32, false,
            static_cast<int64_t>(sizeof(float)) * components, 0);
    const int id = dm.AddAttribute(ga, true, n);
    for (uint32_t i = 0; i < n; ++i) {
      const auto v = value_of(m.vertices[i]);
      dm.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(i), &v);
    }
    return static_cast<int>(dm.attribute(id)->unique_id());
  };
  ids[0] = add(draco::GeometryAttribute::POSITION, 3, [](const scene::Vertex& v) { return v.position; });
  ids[1] = add(draco::GeometryAttribute::NORMAL, 3, [](const scene::Vertex& v) { return v.normal; });
  ids[2] = add(draco::GeometryAttribute::TEX_COORD, 2, [](const scene::Vertex& v) { return v.uv; });
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    draco::Mesh::Face f;
    for (int k = 0; k < 3; ++k) f[k] = draco::PointIndex(m.indices[t + static_cast<size_t>(k)]);
    dm.AddFace(f);
  }
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, position_bits);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
  encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
  draco::EncoderBuffer out;
  const draco::Status st = encoder.EncodeMeshToBuffer(dm, &out);
  EXPECT_TRUE(st.ok()) << st.error_msg_string();
  return {out.data(), out.data() + out.size()};
}

void add_draco_mesh(GlbWriter& w, const scene::Mesh& m, const std::vector<uint8_t>& stream, const int ids[3],
                    size_t declared_vertices) {
  const int view = w.view(stream.data(), stream.size());
  json prim = {
      {"attributes",
       {{"POSITION", w.accessor({{"componentType", 5126}, {"count", declared_vertices}, {"type", "VEC3"},
                                 {"min", vec3_bounds(m.vertices, "min")}, {"max", vec3_bounds(m.vertices, "max")}})},
        {"NORMAL", w.accessor({{"componentType", 5126}, {"count", declared_vertices}, {"type", "VEC3"}})},
        {"TEXCOORD_0", w.accessor({{"componentType", 5126}, {"count", declared_vertices}, {"type", "VEC2"}})}}},
      {"indices", w.accessor({{"componentType", 5125}, {"count", m.indices.size()}, {"type", "SCALAR"}})},
      {"extensions",
       {{"KHR_draco_mesh_compression",
         {{"bufferView", view}, {"attributes", {{"POSITION", ids[0]}, {"NORMAL", ids[1]}, {"TEXCOORD_0", ids[2]}}}}}}}};
  w.json["meshes"].push_back({{"primitives", json::array({prim})}});
  w.json["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  w.json["extensionsRequired"] = {"KHR_draco_mesh_compression"};
}

// The meshopt twin (EXT_meshopt_compression + KHR_mesh_quantization): float positions, normals
// in 8-bit octahedral encoding, indices as TRIANGLES or INDICES; every view decodes into a
// fallback buffer that has no data of its own.
struct MeshoptTwin {
  GlbWriter& w;
  size_t fallback_size = 0;

  int view(const void* raw, size_t count, size_t stride, const char* mode, const char* filter = "NONE") {
    std::vector<uint8_t> packed;
    const std::string m = mode;
    if (m == "ATTRIBUTES") {
      packed.resize(meshopt_encodeVertexBufferBound(count, stride));
      packed.resize(meshopt_encodeVertexBuffer(packed.data(), packed.size(), raw, count, stride));
    } else {
      const auto* idx = static_cast<const unsigned int*>(raw);
      packed.resize(m == "TRIANGLES" ? meshopt_encodeIndexBufferBound(count, count)
                                     : meshopt_encodeIndexSequenceBound(count, count));
      packed.resize(m == "TRIANGLES" ? meshopt_encodeIndexBuffer(packed.data(), packed.size(), idx, count)
                                     : meshopt_encodeIndexSequence(packed.data(), packed.size(), idx, count));
    }
    const size_t source = w.append(packed.data(), packed.size());
    const size_t target = fallback_size;
    fallback_size += (count * stride + 3) / 4 * 4;
    json v = {{"buffer", 1}, {"byteOffset", target}, {"byteLength", count * stride},
              {"extensions",
               {{"EXT_meshopt_compression",
                 {{"buffer", 0}, {"byteOffset", source}, {"byteLength", packed.size()}, {"byteStride", stride},
                  {"count", count}, {"mode", mode}, {"filter", filter}}}}}};
    if (m == "ATTRIBUTES") v["byteStride"] = stride;
    w.json["bufferViews"].push_back(v);
    return static_cast<int>(w.json["bufferViews"].size() - 1);
  }

  void add_mesh(const scene::Mesh& m, const char* index_mode) {
    const size_t n = m.vertices.size();
    std::vector<float> pos, nrm4;
    for (const scene::Vertex& v : m.vertices) {
      pos.insert(pos.end(), {v.position.x, v.position.y, v.position.z});
      nrm4.insert(nrm4.end(), {v.normal.x, v.normal.y, v.normal.z, 0.0f});
    }
    std::vector<int8_t> oct(n * 4);
    meshopt_encodeFilterOct(oct.data(), n, 4, 8, nrm4.data());
    json prim = {
        {"attributes",
         {{"POSITION", w.accessor({{"bufferView", view(pos.data(), n, 12, "ATTRIBUTES")}, {"componentType", 5126},
                                   {"count", n}, {"type", "VEC3"}, {"min", vec3_bounds(m.vertices, "min")},
                                   {"max", vec3_bounds(m.vertices, "max")}})},
          {"NORMAL", w.accessor({{"bufferView", view(oct.data(), n, 4, "ATTRIBUTES", "OCTAHEDRAL")},
                                 {"componentType", 5120}, {"normalized", true}, {"count", n}, {"type", "VEC3"}})}}},
        {"indices", w.accessor({{"bufferView", view(m.indices.data(), m.indices.size(), 4, index_mode)},
                                {"componentType", 5125}, {"count", m.indices.size()}, {"type", "SCALAR"}})}};
    w.json["meshes"].push_back({{"primitives", json::array({prim})}});
  }

  void finish() {
    w.json["buffers"].push_back({{"byteLength", fallback_size},
                                 {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    w.json["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    w.json["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
  }
};

// The loaded scene with an 8 x 8 ground at y = 0 (the loader's default material), ready to trace.
Result<reference::RayScene> on_ground(scene::Scene s) {
  scene::Mesh ground;
  scene::build::add_ground(ground, {0.0f, 0.0f, 0.0f}, 8.0f, 8.0f);
  ground.material = static_cast<uint32_t>(s.materials.size() - 1);
  s.meshes.push_back(ground);
  s.instances.push_back({static_cast<uint32_t>(s.meshes.size() - 1), glm::mat4(1.0f)});
  s.bounds = scene::compute_bounds(s);
  return reference::RayScene::build(s);
}

// The caster's shadow on a ground plane, ray traced (CPU), seen from above and in front.
metrics::MaskImage traced_shadow(scene::Scene s) {
  Result<reference::RayScene> rs = on_ground(std::move(s));
  EXPECT_TRUE(rs);
  scene::Light light;
  light.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
  light.position = -10.0f * light.direction;
  light.size = 2.0f;
  const reference::GBuffer g = reference::primary_gbuffer(*rs, scene::Camera::look_at({1.5f, 3.0f, 4.0f}, {0, 0.3f, 0}), 64, 48);
  metrics::MaskImage mask = reference::trace_visibility(*rs, light, g, {.samples = 16});
  // The comparison means something only where the frame holds the caster's shadow and its penumbra.
  const auto umbra = std::count(mask.pixels.begin(), mask.pixels.end(), 0.0f);
  const auto penumbra = std::count_if(mask.pixels.begin(), mask.pixels.end(), [](float v) { return v > 0 && v < 1; });
  EXPECT_GT(umbra, 20);
  EXPECT_GT(penumbra, 20);
  return mask;
}

float max_difference(const metrics::MaskImage& a, const metrics::MaskImage& b) {
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  float d = 0.0f;
  for (size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) d = std::max(d, std::fabs(a.pixels[i] - b.pixels[i]));
  return d;
}

scene::Scene load(const fs::path& path) {
  Result<scene::Scene> s = scene::load_gltf(path.string());
  EXPECT_TRUE(s) << s.error().to_string();
  return s ? std::move(*s) : scene::Scene{};
}

std::string error_of(const fs::path& path) {
  Result<scene::Scene> s = scene::load_gltf(path.string());
  EXPECT_FALSE(s) << path << " loaded but should not";
  return s ? std::string() : s.error().to_string();
}

// A textured quad in the XZ plane at height 1 (2 x 2 units, UVs 0..1 on TEXCOORD_0 and 1 - uv on
// TEXCOORD_1), alpha-masked by a 2 x 1 texture whose left texel is opaque and right one clear.
GlbWriter masked_quad(const json& texture_info_extensions) {
  GlbWriter w;
  const float pos[] = {-1, 1, -1, 1, 1, -1, 1, 1, 1, -1, 1, 1};
  const float uv0[] = {0, 0, 1, 0, 1, 1, 0, 1};
  const float uv1[] = {1, 1, 0, 1, 0, 0, 1, 0};
  const uint16_t idx[] = {0, 2, 1, 0, 3, 2};
  json prim = {{"attributes",
                {{"POSITION", w.accessor({{"bufferView", w.view(pos, sizeof pos)}, {"componentType", 5126}, {"count", 4},
                                          {"type", "VEC3"}, {"min", {-1, 1, -1}}, {"max", {1, 1, 1}}})},
                 {"TEXCOORD_0", w.accessor({{"bufferView", w.view(uv0, sizeof uv0)}, {"componentType", 5126},
                                            {"count", 4}, {"type", "VEC2"}})},
                 {"TEXCOORD_1", w.accessor({{"bufferView", w.view(uv1, sizeof uv1)}, {"componentType", 5126},
                                            {"count", 4}, {"type", "VEC2"}})}}},
               {"indices", w.accessor({{"bufferView", w.view(idx, sizeof idx)}, {"componentType", 5123}, {"count", 6},
                                       {"type", "SCALAR"}})},
               {"material", 0}};
  w.json["meshes"] = json::array({{{"primitives", json::array({prim})}}});
  // 2 x 1 RGBA: left texel opaque white, right texel clear.
  const fs::path png = test::fresh_temp_dir("gltf_masked_quad_png") / "mask.png";
  const uint8_t texels[] = {255, 255, 255, 255, 255, 255, 255, 0};
  EXPECT_TRUE(write_png(png.string(), 2, 1, 4, texels));
  std::ifstream in(png, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  w.json["images"] = json::array({{{"bufferView", w.view(bytes.data(), bytes.size())}, {"mimeType", "image/png"}}});
  w.json["samplers"] = json::array({{{"magFilter", 9728}, {"minFilter", 9728}}});
  w.json["textures"] = json::array({{{"source", 0}, {"sampler", 0}}});
  json info = {{"index", 0}};
  if (!texture_info_extensions.is_null()) info["extensions"] = texture_info_extensions;
  w.json["materials"] = json::array(
      {{{"alphaMode", "MASK"}, {"doubleSided", true}, {"pbrMetallicRoughness", {{"baseColorTexture", info}}}}});
  w.scene_of_meshes();
  return w;
}

// Visibility of ground points under the quad's left half (u in 0.2..0.4), light straight down.
std::vector<float> under_left_half(const scene::Scene& s) {
  Result<reference::RayScene> rs = on_ground(s);
  EXPECT_TRUE(rs);
  scene::Light light;
  light.direction = {0, -1, 0};
  light.position = {0, 10, 0};
  light.size = 0.0f;
  std::vector<glm::vec3> pts = {{-0.6f, 0, 0}, {-0.4f, 0, 0.5f}, {-0.3f, 0, -0.5f}}, normals(3, glm::vec3(0, 1, 0));
  return reference::trace_visibility(*rs, light, pts, normals, 3, 1, {.samples = 1}).pixels;
}

}  // namespace

TEST(GltfTextureTransform, FollowsTheMatrixTheKhronosSampleChecks) {
  scene::gltf::TextureTransform t;
  t.offset = {0.5f, 0.25f};
  t.scale = {2.0f, 3.0f};
  t.rotation = std::numbers::pi_v<float> / 2;
  // Scale (1, 0) -> (2, 0); a quarter turn takes +u to -v; then the offset.
  const glm::vec2 a = t.apply({1.0f, 0.0f});
  EXPECT_NEAR(a.x, 0.5f, 1e-6f);
  EXPECT_NEAR(a.y, 0.25f - 2.0f, 1e-6f);
  const glm::vec2 b = t.apply({0.0f, 1.0f});  // (0, 3) -> (3, 0)
  EXPECT_NEAR(b.x, 0.5f + 3.0f, 1e-6f);
  EXPECT_NEAR(b.y, 0.25f, 1e-6f);
}

TEST(GltfTextureTransform, IsAppliedToTheCoordinatesTheMaskIsSampledWith) {
  const fs::path dir = test::fresh_temp_dir("gltf_texture_transform");
  masked_quad({{"KHR_texture_transform", {{"offset", {0.25, 0.5}}, {"scale", {0.5, 0.5}}, {"rotation", 0.3}}}})
      .write(dir / "t.glb");
  scene::gltf::TextureTransform t;
  t.offset = {0.25f, 0.5f};
  t.scale = {0.5f, 0.5f};
  t.rotation = 0.3f;
  const scene::Scene s = load(dir / "t.glb");
  ASSERT_EQ(s.meshes.size(), 1u);
  // The quad has no normals, so the loader gives each triangle its own corners, in index order.
  const float uv0[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const size_t corners[6] = {0, 2, 1, 0, 3, 2};
  ASSERT_EQ(s.meshes[0].vertices.size(), 6u);
  for (size_t k = 0; k < 6; ++k) {
    const glm::vec2 want = t.apply({uv0[corners[k]][0], uv0[corners[k]][1]});
    EXPECT_NEAR(s.meshes[0].vertices[k].uv.x, want.x, 1e-6f) << k;
    EXPECT_NEAR(s.meshes[0].vertices[k].uv.y, want.y, 1e-6f) << k;
  }
  // The extension's texCoord overrides the textureInfo's: TEXCOORD_1 (1 - uv) is sampled.
  masked_quad({{"KHR_texture_transform", {{"texCoord", 1}}}}).write(dir / "set1.glb");
  const scene::Scene s1 = load(dir / "set1.glb");
  for (size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(s1.meshes[0].vertices[k].uv.x, 1.0f - uv0[corners[k]][0]) << k;
    EXPECT_EQ(s1.meshes[0].vertices[k].uv.y, 1.0f - uv0[corners[k]][1]) << k;
  }
}

// The ray-traced reference's alpha test sees the transformed mask: the quad's left half casts a
// shadow as it is, none once the transform maps it onto the clear texel, and again once
// TEXCOORD_1 (mirrored) moves the opaque texel back under it... from the other side.
TEST(GltfTextureTransform, AMaskedCasterCastsTheShadowOfTheTransformedMask) {
  const fs::path dir = test::fresh_temp_dir("gltf_texture_transform_shadow");
  masked_quad(json()).write(dir / "plain.glb");
  masked_quad({{"KHR_texture_transform", {{"offset", {0.5, 0.0}}, {"scale", {0.5, 1.0}}}}}).write(dir / "moved.glb");
  masked_quad({{"KHR_texture_transform", {{"texCoord", 1}}}}).write(dir / "mirrored.glb");
  for (float v : under_left_half(load(dir / "plain.glb"))) EXPECT_EQ(v, 0.0f);     // opaque texel: umbra
  for (float v : under_left_half(load(dir / "moved.glb"))) EXPECT_EQ(v, 1.0f);     // u' in 0.6..0.7: clear
  for (float v : under_left_half(load(dir / "mirrored.glb"))) EXPECT_EQ(v, 1.0f);  // 1 - u: clear texel
}

TEST(GltfTextureTransform, NonFiniteValuesAreRefusedWithTheirPointer) {
  const fs::path dir = test::fresh_temp_dir("gltf_texture_transform_bad");
  GlbWriter w = masked_quad({{"KHR_texture_transform", {{"rotation", "a lot"}}}});
  w.write(dir / "r.glb");
  const std::string e = error_of(dir / "r.glb");
  EXPECT_NE(e.find("/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/rotation"),
            std::string::npos) << e;
  EXPECT_NE(e.find("must be a finite number"), std::string::npos) << e;
}

TEST(GltfMeshQuantization, IntegerAttributesAreDequantizedAsTheExtensionStates) {
  const fs::path dir = test::fresh_temp_dir("gltf_quantization");
  GlbWriter w;
  // Normalized SHORT, each VEC3 padded to 8 bytes (a byteStride must be a multiple of 4).
  const int16_t pos[] = {32767, 0, -32768, 0, -32767, 16384, 0, 0, 0, 0, 32767, 0, 0, 0, 0, 0};
  const int8_t nrm[] = {127, 0, 0, 0, 0, -127, 0, 0, 0, 127, 0, 0, 0, 0, 127, 0};    // normalized BYTE, stride 4
  const uint8_t uv[] = {0, 0, 200, 3, 7, 255, 1, 1};                                // UNSIGNED_BYTE, not normalized
  const int pv = w.view(pos, sizeof pos), nv = w.view(nrm, sizeof nrm);
  w.json["bufferViews"][pv]["byteStride"] = 8;
  w.json["bufferViews"][nv]["byteStride"] = 4;
  const uint16_t idx[] = {0, 1, 2, 0, 2, 3};
  json prim = {{"attributes",
                {{"POSITION", w.accessor({{"bufferView", pv}, {"componentType", 5122}, {"normalized", true},
                                          {"count", 4}, {"type", "VEC3"}, {"min", {-1, 0, -1}}, {"max", {1, 1, 1}}})},
                 {"NORMAL", w.accessor({{"bufferView", nv}, {"componentType", 5120}, {"normalized", true},
                                        {"count", 4}, {"type", "VEC3"}})},
                 {"TEXCOORD_0", w.accessor({{"bufferView", w.view(uv, sizeof uv)}, {"componentType", 5121},
                                            {"count", 4}, {"type", "VEC2"}})}}},
               {"indices", w.accessor({{"bufferView", w.view(idx, sizeof idx)}, {"componentType", 5123},
                                       {"count", 6}, {"type", "SCALAR"}})}};
  w.json["meshes"] = json::array({{{"primitives", json::array({prim})}}});
  w.json["extensionsUsed"] = {"KHR_mesh_quantization"};
  w.json["extensionsRequired"] = {"KHR_mesh_quantization"};
  w.scene_of_meshes();
  w.write(dir / "q.glb");
  const scene::Scene s = load(dir / "q.glb");
  ASSERT_EQ(s.meshes.size(), 1u);
  const auto& v = s.meshes[0].vertices;
  EXPECT_EQ(v[0].position, glm::vec3(1.0f, 0.0f, -1.0f));  // -32768 clamps to -1
  EXPECT_EQ(v[1].position.x, -1.0f);
  EXPECT_NEAR(v[1].position.y, 16384.0f / 32767.0f, 1e-7f);
  EXPECT_EQ(v[0].normal, glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(v[1].normal, glm::vec3(0.0f, -1.0f, 0.0f));
  EXPECT_EQ(v[1].uv, glm::vec2(200.0f, 3.0f));  // not normalized: the integers themselves

  // A normal stored as UNSIGNED_BYTE is not one KHR_mesh_quantization allows.
  w.json["accessors"][1]["componentType"] = 5121;
  w.write(dir / "bad_normal.glb");
  const std::string e = error_of(dir / "bad_normal.glb");
  EXPECT_NE(e.find("mesh 0 '' primitive 0 NORMAL"), std::string::npos) << e;
  EXPECT_NE(e.find("KHR_mesh_quantization"), std::string::npos) << e;
}

TEST(GltfMeshopt, DecodesToItsUncompressedTwin) {
  const fs::path dir = test::fresh_temp_dir("gltf_meshopt");
  const scene::Mesh m = caster();
  write_plain_twin(m, dir / "plain.glb");
  GlbWriter packed;
  MeshoptTwin twin{packed};
  twin.add_mesh(m, "TRIANGLES");
  twin.add_mesh(m, "INDICES");
  twin.finish();
  packed.scene_of_meshes();
  packed.write(dir / "meshopt.glb");

  const scene::Scene a = load(dir / "plain.glb"), b = load(dir / "meshopt.glb");
  ASSERT_EQ(b.meshes.size(), 2u);
  for (const scene::Mesh& d : b.meshes) {
    ASSERT_EQ(d.indices, a.meshes[0].indices);  // lossless index codecs
    ASSERT_EQ(d.vertices.size(), a.meshes[0].vertices.size());
    for (size_t i = 0; i < d.vertices.size(); ++i) {
      EXPECT_EQ(d.vertices[i].position, a.meshes[0].vertices[i].position) << i;  // lossless vertex codec
      EXPECT_LT(glm::length(d.vertices[i].normal - a.meshes[0].vertices[i].normal), 0.03f) << i;  // 8-bit octahedral
    }
  }
  scene::Scene one = b;
  one.instances.resize(1);
  EXPECT_LE(max_difference(traced_shadow(a), traced_shadow(one)), 1.0f / 255.0f);
}

TEST(GltfDraco, DecodesToItsUncompressedTwinWithinTheQuantizationError) {
  const fs::path dir = test::fresh_temp_dir("gltf_draco");
  const scene::Mesh m = caster();
  write_plain_twin(m, dir / "plain.glb");
  int ids[3];
  const std::vector<uint8_t> stream = draco_stream(m, 16, ids);
  GlbWriter packed;
  add_draco_mesh(packed, m, stream, ids, m.vertices.size());
  packed.scene_of_meshes();
  packed.write(dir / "draco.glb");

  const scene::Scene a = load(dir / "plain.glb"), b = load(dir / "draco.glb");
  ASSERT_EQ(b.meshes.size(), 1u);
  ASSERT_EQ(b.meshes[0].indices.size(), a.meshes[0].indices.size());
  // Sequential encoding keeps the triangles in order; each corner moves by at most half a
  // quantization step of the 16-bit grid over the mesh's extent (about 2 units).
  const float step = 2.2f / 65535.0f;
  for (size_t k = 0; k < a.meshes[0].indices.size(); ++k) {
    const scene::Vertex& p = a.meshes[0].vertices[a.meshes[0].indices[k]];
    const scene::Vertex& q = b.meshes[0].vertices[b.meshes[0].indices[k]];
    EXPECT_LT(glm::length(p.position - q.position), step) << k;
    EXPECT_LT(glm::length(p.normal - q.normal), 0.01f) << k;
    EXPECT_LT(glm::length(p.uv - q.uv), 1e-3f) << k;
  }
  EXPECT_LE(max_difference(traced_shadow(a), traced_shadow(b)), 1.0f / 255.0f);
}

TEST(GltfDraco, DamagedStreamsAndWrongCountsAreRefusedNamingThePrimitive) {
  const fs::path dir = test::fresh_temp_dir("gltf_draco_bad");
  const scene::Mesh m = caster();
  int ids[3];
  std::vector<uint8_t> stream = draco_stream(m, 14, ids);

  GlbWriter more;  // the stream holds more vertices than the accessors declare
  add_draco_mesh(more, m, stream, ids, m.vertices.size() - 5);
  more.scene_of_meshes();
  more.write(dir / "more.glb");
  std::string e = error_of(dir / "more.glb");
  EXPECT_NE(e.find("mesh 0 '' primitive 0"), std::string::npos) << e;
  EXPECT_NE(e.find("decodes to " + std::to_string(m.vertices.size()) + " vertices; the POSITION accessor declares " +
                   std::to_string(m.vertices.size() - 5)), std::string::npos) << e;
  EXPECT_NE(e.find("KHR_draco_mesh_compression"), std::string::npos) << e;

  for (size_t cut : {stream.size() / 2, size_t{12}, size_t{3}}) {
    GlbWriter truncated;
    const std::vector<uint8_t> part(stream.begin(), stream.begin() + static_cast<std::ptrdiff_t>(cut));
    add_draco_mesh(truncated, m, part, ids, m.vertices.size());
    truncated.scene_of_meshes();
    truncated.write(dir / "truncated.glb");
    e = error_of(dir / "truncated.glb");
    EXPECT_NE(e.find("mesh 0 '' primitive 0: the Draco stream does not decode"), std::string::npos) << cut << ": " << e;
  }

  GlbWriter missing;  // an attribute id the stream does not have
  const int bad_ids[3] = {ids[0], 77, ids[2]};
  add_draco_mesh(missing, m, stream, bad_ids, m.vertices.size());
  missing.scene_of_meshes();
  missing.write(dir / "missing.glb");
  e = error_of(dir / "missing.glb");
  EXPECT_NE(e.find("NORMAL: the Draco stream has no attribute with id 77"), std::string::npos) << e;
}

TEST(GltfMeshopt, DamagedStreamsAndBadParametersAreRefusedNamingTheView) {
  const fs::path dir = test::fresh_temp_dir("gltf_meshopt_bad");
  const scene::Mesh m = caster();
  auto write_and_break = [&](const std::function<void(json&)>& damage) {
    GlbWriter w;
    MeshoptTwin twin{w};
    twin.add_mesh(m, "TRIANGLES");
    twin.finish();
    w.scene_of_meshes();
    damage(w.json);
    w.write(dir / "m.glb");
    return error_of(dir / "m.glb");
  };
  auto ext = [](json& j, int view) -> json& { return j["bufferViews"][view]["extensions"]["EXT_meshopt_compression"]; };
  std::string e = write_and_break([&](json& j) { ext(j, 0)["byteLength"] = ext(j, 0)["byteLength"].get<int>() / 2; });
  EXPECT_NE(e.find("bufferView 0 (EXT_meshopt_compression): the compressed stream does not decode"), std::string::npos) << e;
  e = write_and_break([&](json& j) { ext(j, 2)["byteLength"] = 5; });
  EXPECT_NE(e.find("bufferView 2 (EXT_meshopt_compression): the compressed stream does not decode"), std::string::npos) << e;
  e = write_and_break([&](json& j) { ext(j, 0)["byteStride"] = 6; });
  EXPECT_NE(e.find("ATTRIBUTES needs a byteStride that is a multiple of 4"), std::string::npos) << e;
  e = write_and_break([&](json& j) { ext(j, 2)["count"] = 7; });
  EXPECT_NE(e.find("TRIANGLES needs a count that is a multiple of 3"), std::string::npos) << e;
  e = write_and_break([&](json& j) { ext(j, 1)["filter"] = "QUATERNION"; });
  EXPECT_NE(e.find("QUATERNION needs a byteStride of 8"), std::string::npos) << e;
  e = write_and_break([&](json& j) { ext(j, 0)["count"] = m.vertices.size() * 2; });  // decodes to more than declared
  EXPECT_NE(e.find("more than the bufferView's byteLength"), std::string::npos) << e;
  e = write_and_break([&](json& j) { ext(j, 0)["byteOffset"] = 1u << 30; });
  EXPECT_NE(e.find("lies outside buffer 0"), std::string::npos) << e;
  e = write_and_break([&](json& j) { ext(j, 0)["mode"] = "POINTS"; });
  EXPECT_NE(e.find("/bufferViews/0/extensions/EXT_meshopt_compression/mode"), std::string::npos) << e;
}

TEST(GltfExtensions, RequiredOnesAreDecodedIgnoredWithAWarningOrRefusedWithTheReason) {
  const fs::path dir = test::fresh_temp_dir("gltf_required");
  auto with_required = [&](const std::string& name) {
    GlbWriter w = masked_quad(json());
    w.json["extensionsUsed"] = {name};
    w.json["extensionsRequired"] = {name};
    w.write(dir / "r.glb");
    return scene::load_gltf((dir / "r.glb").string());
  };
  EXPECT_TRUE(with_required("KHR_materials_clearcoat"));  // shading only
  EXPECT_TRUE(with_required("KHR_texture_transform"));
  Result<scene::Scene> refused = with_required("KHR_materials_pbrSpecularGlossiness");
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("which Penumbra refuses: its diffuse texture and factor carry the alpha"),
            std::string::npos) << refused.error().message;
  Result<scene::Scene> unknown = with_required("VENDOR_made_up");
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().message.find("does not know"), std::string::npos) << unknown.error().message;
}

// EXT_mesh_gpu_instancing: each instance is the node's transform times its own translation,
// rotation (here normalized SHORT quaternions) and scale; every instance is in the scene.
TEST(GltfInstancing, EveryInstanceIsPlacedAndCasts) {
  const fs::path dir = test::fresh_temp_dir("gltf_instancing");
  GlbWriter w;
  add_plain_mesh(w, caster());
  const float t[] = {0, 0, 0, 3, 0, 0, 0, 0, -4};
  const int16_t r[] = {0, 0, 0, 32767, 0, 23170, 0, 23170, 0, 0, 0, 32767};  // identity, 90 deg about +Y, identity
  const float sc[] = {1, 1, 1, 1, 1, 1, 2, 2, 2};
  const int tv = w.accessor({{"bufferView", w.view(t, sizeof t)}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  const int rv = w.accessor({{"bufferView", w.view(r, sizeof r)}, {"componentType", 5122}, {"normalized", true},
                             {"count", 3}, {"type", "VEC4"}});
  const int sv = w.accessor({{"bufferView", w.view(sc, sizeof sc)}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  w.scene_of_meshes();
  w.json["nodes"][0]["translation"] = {0, 0.5, 0};
  w.json["nodes"][0]["extensions"] = {
      {"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", tv}, {"ROTATION", rv}, {"SCALE", sv}}}}}};
  w.json["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  w.json["extensionsRequired"] = {"EXT_mesh_gpu_instancing"};
  w.write(dir / "i.glb");
  const scene::Scene s = load(dir / "i.glb");
  ASSERT_EQ(s.instances.size(), 3u);
  auto place = [&](size_t i, glm::vec3 p) { return glm::vec3(s.instances[i].world * glm::vec4(p, 1.0f)); };
  EXPECT_LT(glm::length(place(0, {1, 0, 0}) - glm::vec3(1, 0.5f, 0)), 1e-5f);
  EXPECT_LT(glm::length(place(1, {1, 0, 0}) - glm::vec3(3, 0.5f, -1)), 1e-4f);  // +X turned to -Z, then moved
  EXPECT_LT(glm::length(place(2, {1, 0, 0}) - glm::vec3(2, 0.5f, -4)), 1e-5f);  // doubled, then moved

  // Attributes of different counts, and a rotation stored as raw integers, are refused by name.
  w.json["accessors"][static_cast<size_t>(sv)]["count"] = 2;
  w.write(dir / "counts.glb");
  std::string e = error_of(dir / "counts.glb");
  EXPECT_NE(e.find("node 0 '': its attributes have different counts (3, 3, 2) (EXT_mesh_gpu_instancing)"),
            std::string::npos) << e;
  w.json["accessors"][static_cast<size_t>(sv)]["count"] = 3;
  w.json["accessors"][static_cast<size_t>(rv)]["normalized"] = false;
  w.write(dir / "raw.glb");
  e = error_of(dir / "raw.glb");
  EXPECT_NE(e.find("node 0 '' ROTATION"), std::string::npos) << e;
  EXPECT_NE(e.find("not normalized BYTE or SHORT"), std::string::npos) << e;
}

TEST(GltfExtensions, AnAlphaMaskWithoutAPngOrJpegImageIsRefused) {
  const fs::path dir = test::fresh_temp_dir("gltf_basisu");
  GlbWriter w = masked_quad(json());
  w.json["textures"][0] = {{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}};  // no fallback source
  w.json["extensionsUsed"] = {"KHR_texture_basisu"};
  w.json["extensionsRequired"] = {"KHR_texture_basisu"};
  w.write(dir / "k.glb");
  const std::string e = error_of(dir / "k.glb");
  EXPECT_NE(e.find("material 0"), std::string::npos) << e;
  EXPECT_NE(e.find("has no PNG or JPEG image"), std::string::npos) << e;
}

// docs/gltf.md's table is the loader's table: same extensions, same decision, same reason, and
// each supported one names its tests. On failure the expected rows are printed to paste in.
TEST(GltfExtensions, DocsTableIsTheLoadersTable) {
  std::ifstream in(fs::path(PENUMBRA_SOURCE_DIR) / "docs" / "gltf.md");
  ASSERT_TRUE(in) << "docs/gltf.md is missing";
  std::vector<std::string> documented;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("| `", 0) == 0) documented.push_back(line.substr(0, line.rfind(" | `")));
  std::vector<std::string> expected;
  std::string rows;
  const char* words[] = {"supported", "ignored", "refused"};
  for (const scene::GltfExtension& e : scene::gltf_extensions()) {
    expected.push_back("| `" + std::string(e.name) + "` | " + words[static_cast<int>(e.support)] + " | " +
                       std::string(e.reason));
    rows += expected.back() + " | `...` |\n";
  }
  EXPECT_EQ(documented, expected) << "docs/gltf.md's table should read:\n" << rows;
}

// Found by fuzz_gltf: a compressed .glb cut short, its header still giving the old length. The
// loader rewrites such a file's JSON for tinygltf and must not make its lengths agree again.
TEST(GltfExtensions, ACompressedGlbCutShortIsRefusedBeforeItIsRewritten) {
  const fs::path dir = test::fresh_temp_dir("gltf_cut_glb");
  GlbWriter w;
  MeshoptTwin twin{w};
  twin.add_mesh(caster(), "TRIANGLES");
  twin.finish();
  w.scene_of_meshes();
  w.write(dir / "m.glb");
  const auto size = fs::file_size(dir / "m.glb");
  fs::resize_file(dir / "m.glb", size - 8);
  std::string e = error_of(dir / "m.glb");
  EXPECT_NE(e.find("invalid or truncated .glb file: its header gives a length of " + std::to_string(size) +
                   " bytes; the file has " + std::to_string(size - 8)), std::string::npos) << e;
  // The header fixed, the BIN chunk now runs past the end.
  std::fstream f(dir / "m.glb", std::ios::in | std::ios::out | std::ios::binary);
  const auto shorter = static_cast<uint32_t>(size - 8);
  f.seekp(8);
  f.write(reinterpret_cast<const char*>(&shorter), 4);
  f.close();
  e = error_of(dir / "m.glb");
  EXPECT_NE(e.find("its BIN chunk of"), std::string::npos) << e;
  EXPECT_NE(e.find("runs past the end of the file"), std::string::npos) << e;
}
