#include "scene/gltf_draco.h"

#include <cmath>
#include <memory>

#include <draco/compression/decode.h>
#include <tiny_gltf.h>

namespace penumbra::scene::gltf {

namespace {

constexpr const char* kExtension = " (KHR_draco_mesh_compression)";

// The accessor count a glTF attribute declares, or -1 when the primitive has no such attribute.
long long declared_count(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& name) {
  const auto it = primitive.attributes.find(name);
  if (it == primitive.attributes.end() || it->second < 0 ||
      static_cast<size_t>(it->second) >= model.accessors.size())
    return -1;
  return static_cast<long long>(model.accessors[static_cast<size_t>(it->second)].count);
}

template <int N>
Result<std::vector<glm::vec<N, float>>> read_attribute(const draco::Mesh& mesh, const DracoPrimitive& draco,
                                                       const std::string& name, const std::string& file,
                                                       const std::string& where) {
  const int id = draco.attributes.at(name);
  const draco::PointAttribute* a = mesh.GetAttributeByUniqueId(static_cast<uint32_t>(id));
  if (!a) return file_error(file, name + ": the Draco stream has no attribute with id " + std::to_string(id) + kExtension, where);
  if (a->num_components() < N)
    return file_error(file, name + ": Draco attribute " + std::to_string(id) + " has " +
                                std::to_string(a->num_components()) + " components, " + std::to_string(N) +
                                " expected" + kExtension, where);
  std::vector<glm::vec<N, float>> out(mesh.num_points());
  for (draco::PointIndex::ValueType i = 0; i < mesh.num_points(); ++i) {
    float v[4] = {0, 0, 0, 0};
    if (!a->ConvertValue<float>(a->mapped_index(draco::PointIndex(i)), static_cast<int8_t>(N), v))
      return file_error(file, name + ": Draco attribute " + std::to_string(id) + " does not convert to float" + kExtension, where);
    for (int c = 0; c < N; ++c) {
      if (!std::isfinite(v[c]))
        return file_error(file, name + " element " + std::to_string(i) + " is not finite (NaN or infinity)" + kExtension, where);
      out[i][c] = v[c];
    }
  }
  return out;
}

}  // namespace

Result<VertexArrays> decode_draco_primitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                            const DracoPrimitive& draco, const std::string& uv_attribute,
                                            const std::string& file, const std::string& where) {
  const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(draco.buffer_view)];
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
    return file_error(file, "bufferView " + std::to_string(draco.buffer_view) + " refers to missing buffer " +
                                std::to_string(view.buffer) + kExtension, where);
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<size_t>(view.buffer)].data;
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
    return file_error(file, "the Draco stream's bufferView " + std::to_string(draco.buffer_view) +
                                " lies outside its buffer" + kExtension, where);
  if (!draco.attributes.count("POSITION"))
    return file_error(file, "the Draco stream has no POSITION attribute" + std::string(kExtension), where);

  draco::DecoderBuffer in;
  in.Init(reinterpret_cast<const char*>(buffer.data() + view.byteOffset), view.byteLength);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&in);
  if (!decoded.ok())
    return file_error(file, "the Draco stream does not decode (" + shortened(decoded.status().error_msg_string(), 120) +
                                "): truncated or damaged" + kExtension, where);
  const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
  if (!mesh) return file_error(file, "the Draco stream decodes to no mesh" + std::string(kExtension), where);

  const long long declared = declared_count(model, primitive, "POSITION");
  if (declared != static_cast<long long>(mesh->num_points()))
    return file_error(file, "the Draco stream decodes to " + std::to_string(mesh->num_points()) +
                                " vertices; the POSITION accessor declares " + std::to_string(declared) + kExtension,
                      where);
  VertexArrays out;
  auto positions = read_attribute<3>(*mesh, draco, "POSITION", file, where);
  if (!positions) return positions.error();
  out.positions = std::move(*positions);
  if (draco.attributes.count("NORMAL")) {
    auto normals = read_attribute<3>(*mesh, draco, "NORMAL", file, where);
    if (!normals) return normals.error();
    out.normals = std::move(*normals);
  }
  if (!uv_attribute.empty() && draco.attributes.count(uv_attribute)) {
    auto uvs = read_attribute<2>(*mesh, draco, uv_attribute, file, where);
    if (!uvs) return uvs.error();
    out.uvs = std::move(*uvs);
  }
  const size_t faces = mesh->num_faces();
  if (faces == 0) return file_error(file, "the Draco stream decodes to no triangles" + std::string(kExtension), where);
  if (draco.indices >= 0 && model.accessors[static_cast<size_t>(draco.indices)].count != faces * 3)
    return file_error(file, "the Draco stream decodes to " + std::to_string(faces * 3) +
                                " indices; the index accessor declares " +
                                std::to_string(model.accessors[static_cast<size_t>(draco.indices)].count) + kExtension,
                      where);
  out.indices.reserve(faces * 3);
  for (draco::FaceIndex::ValueType f = 0; f < faces; ++f)
    for (int k = 0; k < 3; ++k) {
      const uint32_t index = mesh->face(draco::FaceIndex(f))[k].value();
      if (index >= mesh->num_points())
        return file_error(file, "the Draco stream has index " + std::to_string(index) + " past its " +
                                    std::to_string(mesh->num_points()) + " vertices" + kExtension, where);
      out.indices.push_back(index);
    }
  return out;
}

}  // namespace penumbra::scene::gltf
