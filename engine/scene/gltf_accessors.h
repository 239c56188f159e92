#pragma once
// Bounds-checked reading of glTF accessors. tinygltf parses the JSON but does not promise that
// an accessor's offset/stride/count lie inside its buffer, so every read goes through here:
// hostile files produce an Error naming the accessor, never an out-of-bounds read.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "util/error.h"

namespace tinygltf {
class Model;
}

namespace penumbra::scene::gltf {

// A validated window onto an accessor's bytes: element i starts at data + i * stride and
// `element_size` bytes of it are readable.
struct AccessorView {
  const uint8_t* data = nullptr;
  size_t count = 0;
  size_t stride = 0;
  size_t element_size = 0;
  int component_type = 0;  // TINYGLTF_COMPONENT_TYPE_*
  int components = 0;      // 1 (SCALAR) .. 4 (VEC4)
  bool normalized = false;
};

// `what` names the use ("POSITION of mesh 'x' primitive 0") for error messages.
Result<AccessorView> view_accessor(const tinygltf::Model& model, int accessor, const std::string& file,
                                   const std::string& what);

// Attributes are FLOAT or, as KHR_mesh_quantization allows, BYTE / UNSIGNED_BYTE / SHORT /
// UNSIGNED_SHORT, normalized or not (normals: normalized BYTE or SHORT only), dequantized to
// float; every value must be finite.
// (rotation: EXT_mesh_gpu_instancing's quaternions, the same rule as normals.)
enum class AttributeKind { position, normal, texcoord, rotation };
Result<std::vector<glm::vec3>> read_vec3(const tinygltf::Model& model, int accessor, AttributeKind kind,
                                         const std::string& file, const std::string& what);
Result<std::vector<glm::vec4>> read_vec4(const tinygltf::Model& model, int accessor, AttributeKind kind,
                                         const std::string& file, const std::string& what);
Result<std::vector<glm::vec2>> read_uv(const tinygltf::Model& model, int accessor,
                                       const std::string& file, const std::string& what);
// A primitive's vertex data as the loader uses it, from accessors or a decoded Draco stream.
struct VertexArrays {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // empty: none in the file
  std::vector<glm::vec2> uvs;      // the texture coordinate set the material samples; empty: none
  std::vector<uint32_t> indices;   // empty: not indexed
};

// Indices: unsigned byte / short / int; each must be < vertex_count.
Result<std::vector<uint32_t>> read_indices(const tinygltf::Model& model, int accessor,
                                           size_t vertex_count, const std::string& file,
                                           const std::string& what);

}  // namespace penumbra::scene::gltf
