#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <spdlog/spdlog.h>
#include <tiny_gltf.h>

#include "scene/framing.h"
#include "scene/glb_container.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_draco.h"
#include "scene/gltf_extension_data.h"
#include "scene/gltf_extension_table.h"
#include "scene/gltf_instancing.h"
#include "scene/gltf_meshopt.h"
#include "scene/gltf_spec_checks.h"
#include "util/file_read.h"
#include "util/json_text.h"

namespace penumbra::scene {
namespace {

// tinygltf takes a 32-bit size; 1 GiB is far above any model we have met (the largest real
// asset we test, 216k triangles with textures, is under 20 MB).
constexpr std::size_t kMaxGltfFileBytes = std::size_t{1} << 30;

const char* mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS: return "POINTS";
    case TINYGLTF_MODE_LINE: return "LINES";
    case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLES: return "TRIANGLES";
    case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
    default: return "unknown";
  }
}

// Any channel layout tinygltf decodes (1-4 channels, 8 or 16 bits) -> RGBA8.
Result<Image> convert_image(const tinygltf::Image& src, const std::string& file, size_t index) {
  const std::string where = "image " + std::to_string(index) + " '" + shortened(src.uri + src.name) + "'";
  const int bytes = src.bits == 16 ? 2 : 1;
  // tinygltf leaves an external image it could not read undecoded: say whether the file is there.
  if (src.image.empty() && !src.uri.empty() && src.uri.rfind("data:", 0) != 0) {
    const std::filesystem::path image = std::filesystem::path(file).parent_path() / src.uri;
    std::error_code ec;
    if (!std::filesystem::exists(image, ec))
      return file_error(file, "image file '" + shortened(src.uri) + "' is missing (looked next to the file)", where);
    return file_error(file, "image file '" + shortened(src.uri) + "' could not be decoded (PNG or JPEG expected)",
                      where);
  }
  if (src.width <= 0 || src.height <= 0 || src.component < 1 || src.component > 4 ||
      (src.bits != 8 && src.bits != 16))
    return file_error(file, "image was not decoded (width " + std::to_string(src.width) + ", channels " +
                                std::to_string(src.component) + ", bits " + std::to_string(src.bits) + ")",
                      where);
  const size_t pixels = static_cast<size_t>(src.width) * static_cast<size_t>(src.height);
  if (src.image.size() < pixels * static_cast<size_t>(src.component * bytes))
    return file_error(file, "decoded image data is shorter than width x height x channels", where);
  Image img;
  img.name = src.name.empty() ? src.uri : src.name;
  img.width = src.width;
  img.height = src.height;
  img.pixels.resize(pixels * 4);
  for (size_t p = 0; p < pixels; ++p) {
    uint8_t c[4] = {0, 0, 0, 255};
    for (int k = 0; k < src.component; ++k)  // 16-bit: keep the high byte (little endian)
      c[k] = src.image[(p * static_cast<size_t>(src.component) + static_cast<size_t>(k)) * bytes + (bytes - 1)];
    if (src.component == 1 || src.component == 2) {  // grey (+alpha)
      c[3] = src.component == 2 ? c[1] : 255;
      c[1] = c[2] = c[0];
    }
    std::copy(c, c + 4, img.pixels.begin() + static_cast<std::ptrdiff_t>(p * 4));
  }
  return img;
}

Material convert_material(const tinygltf::Model& model, const tinygltf::Material& m) {
  Material out;
  out.name = m.name;
  const auto& f = m.pbrMetallicRoughness.baseColorFactor;
  if (f.size() == 4) out.base_color_factor = glm::vec4(f[0], f[1], f[2], f[3]);
  const int tex = m.pbrMetallicRoughness.baseColorTexture.index;
  if (tex >= 0 && static_cast<size_t>(tex) < model.textures.size()) {
    const int source = model.textures[static_cast<size_t>(tex)].source;
    if (source >= 0 && static_cast<size_t>(source) < model.images.size()) out.base_color_texture = source;
  }
  out.alpha_mode = m.alphaMode == "MASK" ? AlphaMode::mask
                   : m.alphaMode == "BLEND" ? AlphaMode::blend : AlphaMode::opaque;
  out.alpha_cutoff = static_cast<float>(m.alphaCutoff);
  out.double_sided = m.doubleSided;
  return out;
}

// Flat normals: de-index so every triangle owns its three vertices, then use the face normal.
void make_flat_normals(Mesh& mesh) {
  std::vector<Vertex> flat;
  flat.reserve(mesh.indices.size());
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    Vertex v[3] = {mesh.vertices[mesh.indices[t]], mesh.vertices[mesh.indices[t + 1]],
                   mesh.vertices[mesh.indices[t + 2]]};
    glm::vec3 n = glm::cross(v[1].position - v[0].position, v[2].position - v[0].position);
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);  // degenerate triangle: any unit normal
    for (Vertex& x : v) { x.normal = n; flat.push_back(x); }
  }
  mesh.vertices = std::move(flat);
  mesh.indices.resize(mesh.vertices.size());
  for (size_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = static_cast<uint32_t>(i);
}

// Which texture coordinates the base colour texture samples, and how they are transformed.
struct BaseColorCoordinates {
  int set = 0;  // TEXCOORD_<set>
  const gltf::TextureTransform* transform = nullptr;
};

BaseColorCoordinates base_color_coordinates(const tinygltf::Model& model, int material,
                                            const gltf::ExtensionData& extensions) {
  BaseColorCoordinates out;
  if (material < 0 || static_cast<size_t>(material) >= model.materials.size()) return out;
  out.set = model.materials[static_cast<size_t>(material)].pbrMetallicRoughness.baseColorTexture.texCoord;
  if (const auto it = extensions.base_color_transform.find(static_cast<size_t>(material));
      it != extensions.base_color_transform.end()) {
    out.transform = &it->second;
    if (it->second.tex_coord) out.set = *it->second.tex_coord;  // the extension's texCoord overrides
  }
  out.set = std::max(out.set, 0);
  return out;
}

// The vertex arrays of a primitive stored in accessors (plain, quantized or meshopt-decoded).
Result<gltf::VertexArrays> read_accessors(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                                          const std::string& uv_attribute, const std::string& where,
                                          const std::string& file) {
  gltf::VertexArrays out;
  const auto pos_it = prim.attributes.find("POSITION");
  if (pos_it == prim.attributes.end()) return file_error(file, "primitive has no POSITION attribute", where);
  auto positions = gltf::read_vec3(model, pos_it->second, gltf::AttributeKind::position, file, where + " POSITION");
  if (!positions) return positions.error();
  out.positions = std::move(*positions);
  if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
    auto normals = gltf::read_vec3(model, it->second, gltf::AttributeKind::normal, file, where + " NORMAL");
    if (!normals) return normals.error();
    out.normals = std::move(*normals);
  }
  if (auto it = prim.attributes.find(uv_attribute); !uv_attribute.empty() && it != prim.attributes.end()) {
    auto uvs = gltf::read_uv(model, it->second, file, where + " " + uv_attribute);
    if (!uvs) return uvs.error();
    out.uvs = std::move(*uvs);
  }
  if (prim.indices >= 0) {
    auto idx = gltf::read_indices(model, prim.indices, out.positions.size(), file, where + " indices");
    if (!idx) return idx.error();
    out.indices = std::move(*idx);
  }
  return out;
}

Result<Mesh> convert_primitive(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                               const gltf::DracoPrimitive* draco, const BaseColorCoordinates& uv,
                               const std::string& where, uint32_t default_material, const std::string& file) {
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES)
    return file_error(file, std::string("unsupported primitive mode ") + mode_name(mode) + " (" +
                                std::to_string(mode) + "); only TRIANGLES (4) is supported", where);
  const std::string uv_attribute = "TEXCOORD_" + std::to_string(uv.set);
  Result<gltf::VertexArrays> arrays = draco ? gltf::decode_draco_primitive(model, prim, *draco, uv_attribute, file, where)
                                            : read_accessors(model, prim, uv_attribute, where, file);
  if (!arrays) return arrays.error();
  const size_t n = arrays->positions.size();
  if (!arrays->normals.empty() && arrays->normals.size() != n)
    return file_error(file, "NORMAL count differs from POSITION count", where);
  if (!arrays->uvs.empty() && arrays->uvs.size() != n)
    return file_error(file, uv_attribute + " count differs from POSITION count", where);

  Mesh mesh;
  mesh.vertices.resize(n);
  for (size_t i = 0; i < n; ++i) {
    mesh.vertices[i].position = arrays->positions[i];
    if (!arrays->normals.empty()) mesh.vertices[i].normal = arrays->normals[i];
    // KHR_texture_transform is affine, so applying it to the vertices is exact under linear
    // interpolation, and every consumer (rasterised maps, both references) sees the same mask.
    if (!arrays->uvs.empty()) mesh.vertices[i].uv = uv.transform ? uv.transform->apply(arrays->uvs[i]) : arrays->uvs[i];
  }
  if (!arrays->indices.empty()) {
    mesh.indices = std::move(arrays->indices);
  } else {
    mesh.indices.resize(n);
    for (size_t i = 0; i < n; ++i) mesh.indices[i] = static_cast<uint32_t>(i);
  }
  if (mesh.indices.size() % 3 != 0)
    return file_error(file, "TRIANGLES primitive has " + std::to_string(mesh.indices.size()) +
                                " indices, not a multiple of 3", where);
  if (arrays->normals.empty()) make_flat_normals(mesh);
  mesh.material = prim.material >= 0 && static_cast<size_t>(prim.material) < model.materials.size()
                      ? static_cast<uint32_t>(prim.material) : default_material;
  return mesh;
}

// The KHR_lights_punctual light a node refers to, placed with the node's world transform.
Result<SceneLight> convert_light(const tinygltf::Model& model, int index, const glm::mat4& world,
                                 const std::string& file, const std::string& where) {
  if (index < 0 || static_cast<size_t>(index) >= model.lights.size())
    return file_error(file, "KHR_lights_punctual light index " + std::to_string(index) + " does not exist (" +
                                std::to_string(model.lights.size()) + " lights)", where);
  const tinygltf::Light& gl = model.lights[static_cast<size_t>(index)];
  SceneLight out;
  out.name = gl.name;
  Light& l = out.light;
  if (gl.type == "directional") l.type = LightType::directional;
  else if (gl.type == "spot") l.type = LightType::spot;
  else if (gl.type == "point") l.type = LightType::point;
  else
    return file_error(file, "KHR_lights_punctual light " + std::to_string(index) + " has type '" + gl.type +
                                "'; expected directional, spot or point", where);
  l.position = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  const glm::vec3 forward = glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
  l.direction = glm::length(forward) > 0.0f ? glm::normalize(forward) : glm::vec3(0.0f, 0.0f, -1.0f);
  l.size = 0.0f;
  if (gl.color.size() == 3) l.color = glm::vec3(gl.color[0], gl.color[1], gl.color[2]);
  l.intensity = static_cast<float>(gl.intensity);
  out.range = static_cast<float>(gl.range);
  if (l.type == LightType::spot) {
    l.spot_angle = static_cast<float>(gl.spot.outerConeAngle);
    out.inner_cone_angle = static_cast<float>(gl.spot.innerConeAngle);
  }
  return out;
}

// The light index of a node's KHR_lights_punctual extension, or -1.
int node_light(const tinygltf::Node& node) {
  const auto it = node.extensions.find("KHR_lights_punctual");
  if (it == node.extensions.end() || !it->second.IsObject() || !it->second.Has("light")) return -1;
  const tinygltf::Value& v = it->second.Get("light");
  return v.IsNumber() ? v.GetNumberAsInt() : -1;
}

glm::mat4 local_transform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::dmat4 m = glm::make_mat4(node.matrix.data());  // glTF is column-major like GLM
    return glm::mat4(m);
  }
  glm::mat4 t(1.0f), r(1.0f), s(1.0f);
  if (node.translation.size() == 3)
    t[3] = glm::vec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  if (node.rotation.size() == 4)  // glTF quaternion order is (x, y, z, w)
    r = glm::mat4_cast(glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                                 static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2])));
  if (node.scale.size() == 3)
    s = glm::scale(glm::mat4(1.0f), glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
  return t * r * s;
}

}  // namespace

Result<Scene> load_gltf(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return file_error(path, "file not found (expected a .gltf or .glb file)");

  const bool binary = std::filesystem::path(path).extension() == ".glb";
  Result<std::string> bytes = read_file_whole(path, kMaxGltfFileBytes);
  if (!bytes) return bytes.error();
  std::string_view json_text = *bytes;
  if (binary) {
    Result<glb::Chunks> chunks = glb::split(*bytes, path);
    if (!chunks) return chunks.error();
    json_text = chunks->json;
  }
  // The JSON part goes through the one nesting limit before tinygltf's parser (which recurses)
  // sees it; duplicate keys are left to the parser: a glTF file is not ours to be strict about.
  if (std::optional<JsonTextProblem> p = scan_json_text(json_text, /*duplicate_keys=*/false)) {
    Error e = file_error(path, "glTF JSON: " + p->message);
    if (!binary) {
      e.line = p->line;
      e.column = p->column;
    }
    return e;
  }
  if (Status s = check_gltf_spec_values(json_text, path); !s) return s.error();

  Result<gltf::PreparedFile> prepared = gltf::prepare_extensions(std::move(*bytes), binary, path);
  if (!prepared) return prepared.error();
  const gltf::ExtensionData& extensions = prepared->extensions;
  const std::string& file_bytes = prepared->bytes;

  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  bool ok = false;
  try {
    const auto size = static_cast<unsigned int>(file_bytes.size());
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                              reinterpret_cast<const unsigned char*>(file_bytes.data()), size, base_dir)
                : loader.LoadASCIIFromString(&model, &err, &warn, file_bytes.data(), size, base_dir);
  } catch (const std::exception& e) {
    // tinygltf indexes some arrays unchecked with .at(): a malformed file throws instead of
    // returning its error (found by fuzz_gltf).
    return file_error(path, std::string("not a valid glTF file (") + e.what() + ")");
  }
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    if (const size_t at = err.find("File not found : "); at != std::string::npos) {
      const std::string missing = err.substr(at + 17, err.find('\n', at) - at - 17);
      return file_error(path, "buffer file '" + shortened(missing) + "' is missing (looked next to the file)");
    }
    if (err.find("cannot decode image") != std::string::npos)
      return file_error(path, "an image could not be decoded (PNG or JPEG expected): " + shortened(err, 200));
    return file_error(path, std::string("invalid or truncated ") + (binary ? ".glb" : ".gltf") + " file: " +
                                shortened(err, 300));
  }
  if (Status st = check_required_gltf_extensions(model.extensionsRequired, path); !st) return st.error();
  if (Status st = gltf::decode_meshopt_views(model, extensions, path); !st) return st.error();

  Scene scene;
  scene.name = std::filesystem::path(path).stem().string();
  scene.source_file = path;
  for (size_t i = 0; i < model.images.size(); ++i) {
    Result<Image> img = convert_image(model.images[i], path, i);
    if (!img) return img.error();
    scene.images.push_back(std::move(*img));
  }
  for (size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& m = model.materials[i];
    scene.materials.push_back(convert_material(model, m));
    // A texture only in KTX2, WebP or AVIF (no PNG or JPEG source) is drawn untextured; for an
    // alpha-tested material that would lose the mask its shadow is cut by.
    const int tex = m.pbrMetallicRoughness.baseColorTexture.index;
    if (scene.materials.back().alpha_mode == AlphaMode::mask && tex >= 0 &&
        scene.materials.back().base_color_texture < 0)
      return file_error(path, "the alpha-masked material's base colour texture " + std::to_string(tex) +
                                  " has no PNG or JPEG image (only an extension's format, such as KTX2, WebP or "
                                  "AVIF, which Penumbra does not decode): its shadow would lose the mask",
                        "material " + std::to_string(i) + " '" + shortened(m.name) + "'");
  }
  const uint32_t default_material = static_cast<uint32_t>(scene.materials.size());
  scene.materials.push_back(Material{.name = "default"});

  // glTF mesh i -> scene.meshes[first[i] .. first[i] + count[i]) (one Mesh per primitive).
  std::vector<size_t> first(model.meshes.size()), count(model.meshes.size());
  for (size_t mi = 0; mi < model.meshes.size(); ++mi) {
    first[mi] = scene.meshes.size();
    const tinygltf::Mesh& gm = model.meshes[mi];
    for (size_t pi = 0; pi < gm.primitives.size(); ++pi) {
      const std::string where = "mesh " + std::to_string(mi) + " '" + gm.name + "' primitive " + std::to_string(pi);
      const tinygltf::Primitive& prim = gm.primitives[pi];
      const auto draco = extensions.draco.find({mi, pi});
      Result<Mesh> mesh = convert_primitive(model, prim, draco == extensions.draco.end() ? nullptr : &draco->second,
                                            base_color_coordinates(model, prim.material, extensions), where,
                                            default_material, path);
      if (!mesh) return mesh.error();
      mesh->name = gm.name;
      scene.meshes.push_back(std::move(*mesh));
    }
    count[mi] = scene.meshes.size() - first[mi];
  }
  if (scene.meshes.empty()) return file_error(path, "file contains no meshes");

  // Flatten the node hierarchy. A depth cap guards against cyclic children in hostile files, a
  // visit cap against children shared along many paths (a DAG of 41 nodes can expand to 2^40).
  size_t visits = 0;
  std::function<Status(int, const glm::mat4&, int)> visit = [&](int ni, const glm::mat4& parent,
                                                                int depth) -> Status {
    if (ni < 0 || static_cast<size_t>(ni) >= model.nodes.size())
      return file_error(path, "node index " + std::to_string(ni) + " does not exist");
    if (depth > kMaxNodeDepth)
      return file_error(path, "node hierarchy deeper than " + std::to_string(kMaxNodeDepth) + " levels (cycle?)",
                        "node " + std::to_string(ni));
    if (++visits > kMaxNodeVisits || scene.instances.size() > kMaxInstances)
      return file_error(path, "the node hierarchy expands to more than " + std::to_string(kMaxInstances) +
                                  " mesh instances or " + std::to_string(kMaxNodeVisits) +
                                  " node visits (nodes that share children multiply)", "node " + std::to_string(ni));
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(ni)];
    const glm::mat4 world = parent * local_transform(node);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(world[c][r]))
          return file_error(path, "transform is not finite (NaN or infinity)",
                            "node " + std::to_string(ni) + " '" + shortened(node.name) + "'");
    if (node.mesh >= 0 && static_cast<size_t>(node.mesh) < model.meshes.size()) {
      const std::string where = "node " + std::to_string(ni) + " '" + shortened(node.name) + "'";
      auto instances = gltf::node_instances(model, node, path, where);
      if (!instances) return instances.error();
      const std::vector<glm::mat4> placements = *instances ? **instances : std::vector<glm::mat4>{glm::mat4(1.0f)};
      if (*instances && scene.instances.size() + placements.size() * count[static_cast<size_t>(node.mesh)] > kMaxInstances)
        return file_error(path, "its instances take the scene past " + std::to_string(kMaxInstances) +
                                    " mesh instances (EXT_mesh_gpu_instancing)", where);
      for (const glm::mat4& placement : placements)
        for (size_t k = 0; k < count[static_cast<size_t>(node.mesh)]; ++k)
          scene.instances.push_back({static_cast<uint32_t>(first[static_cast<size_t>(node.mesh)] + k), world * placement});
    }
    if (const int light = node_light(node); light >= 0 || node.extensions.count("KHR_lights_punctual")) {
      Result<SceneLight> l = convert_light(model, light, world, path, "node " + std::to_string(ni) + " '" + node.name + "'");
      if (!l) return l.error();
      scene.lights.push_back(std::move(*l));
    }
    if (node.camera >= 0 && static_cast<size_t>(node.camera) < model.cameras.size()) {
      const tinygltf::Camera& cam = model.cameras[static_cast<size_t>(node.camera)];
      if (cam.type == "perspective") {
        const auto& p = cam.perspective;
        scene.cameras.push_back({cam.name.empty() ? node.name : cam.name,
                                 camera_from_node(world, static_cast<float>(p.yfov), static_cast<float>(p.znear),
                                                  static_cast<float>(p.zfar))});
      } else {
        spdlog::warn("{}: node {} '{}': {} camera ignored (only perspective cameras are offered)", path, ni,
                     node.name, cam.type);
      }
    }
    for (int child : node.children)
      if (Status s = visit(child, world, depth + 1); !s) return s;
    return {};
  };
  if (!model.scenes.empty()) {
    const size_t si = model.defaultScene >= 0 && static_cast<size_t>(model.defaultScene) < model.scenes.size()
                          ? static_cast<size_t>(model.defaultScene) : 0;
    for (int root : model.scenes[si].nodes)
      if (Status s = visit(root, glm::mat4(1.0f), 0); !s) return s.error();
  } else {
    // No scene: show every mesh once at the origin rather than nothing.
    for (size_t m = 0; m < scene.meshes.size(); ++m) scene.instances.push_back({static_cast<uint32_t>(m), glm::mat4(1.0f)});
  }
  if (scene.instances.empty()) return file_error(path, "the default scene places no meshes (no node refers to a mesh)");

  scene.bounds = compute_bounds(scene);
  const double original_radius = 0.5 * glm::length(glm::dvec3(scene.bounds.max) - glm::dvec3(scene.bounds.min));
  if (const float s = fit_scene_scale(scene); s != 1.0f)
    spdlog::warn("{}: the scene's bounding sphere has radius {:g} world units, outside [{:g}, {:g}]; "
                 "rendering it scaled by {:g} (radius {:g})", path, original_radius, kMinSceneRadius,
                 kMaxSceneRadius, s, scene.bounds.radius());
  scene.camera = fit_camera(scene.bounds, 16.0f / 9.0f);
  // The file's own light when it has one, else one that throws the shadows towards the camera.
  if (std::optional<Light> own = file_light(scene)) scene.light = *own;
  else scene.light = default_light(scene.bounds, scene.camera.forward());
  return scene;
}

}  // namespace penumbra::scene
