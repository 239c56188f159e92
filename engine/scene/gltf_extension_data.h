#pragma once
// What the loader needs from the geometry and texture extensions, read from the file's JSON
// before tinygltf parses it, and the file rewritten where Debian's tinygltf 2.7.0 (built without
// Draco) would refuse it:
//   - a Draco primitive's index accessor has no bufferView (its data is in the Draco stream):
//     its `indices` is taken out of the JSON tinygltf sees and kept here;
//   - an EXT_meshopt_compression fallback buffer has no data at all (it is what decoding fills):
//     tinygltf would take it for a .glb's binary chunk, so it is given a 3-byte placeholder here
//     and its real size is kept.
// Every extension value is checked here (types, ranges, finite numbers), each error naming its
// JSON pointer.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "util/error.h"

namespace penumbra::scene::gltf {

// KHR_texture_transform on a textureInfo: scale, then rotate, then offset, the rotation turning
// the way the Khronos TextureTransformTest sample checks (its arrows point at the green
// markers): u' = cos r u + sin r v, v' = -sin r u + cos r v.
struct TextureTransform {
  glm::vec2 offset{0.0f}, scale{1.0f};
  float rotation = 0.0f;          // radians
  std::optional<int> tex_coord;   // overrides the textureInfo's texCoord
  glm::vec2 apply(glm::vec2 uv) const;
};

// KHR_draco_mesh_compression on a primitive: the stream's bufferView and each glTF attribute's
// Draco unique id.
struct DracoPrimitive {
  int buffer_view = -1;
  std::map<std::string, int> attributes;
  int indices = -1;  // the primitive's index accessor (count and type), -1 when it has none
};

// EXT_meshopt_compression on a bufferView: where the compressed bytes are and how to decode them
// into the bufferView's own range.
struct MeshoptView {
  enum class Mode { attributes, triangles, indices };
  enum class Filter { none, octahedral, quaternion, exponential };
  int buffer = -1;
  std::size_t byte_offset = 0, byte_length = 0, byte_stride = 0, count = 0;
  Mode mode = Mode::attributes;
  Filter filter = Filter::none;
};

struct ExtensionData {
  std::map<std::pair<std::size_t, std::size_t>, DracoPrimitive> draco;  // by (mesh, primitive)
  std::map<std::size_t, MeshoptView> meshopt;                           // by bufferView
  std::map<std::size_t, std::size_t> fallback_buffers;  // buffer -> byteLength, data made by decoding
  std::map<std::size_t, TextureTransform> base_color_transform;  // by material
};

struct PreparedFile {
  ExtensionData extensions;
  std::string bytes;  // the file as tinygltf is to read it (unchanged when nothing needed rewriting)
};

// `bytes`: the whole .gltf or .glb. Text that is not JSON is passed on unchanged for tinygltf to
// report.
Result<PreparedFile> prepare_extensions(std::string bytes, bool binary, const std::string& file);

}  // namespace penumbra::scene::gltf
