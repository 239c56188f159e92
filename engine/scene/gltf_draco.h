#pragma once
// KHR_draco_mesh_compression: a primitive's Draco stream decoded with libdraco into the arrays
// the loader builds its mesh from. The decoded mesh must match what the file's accessors declare
// (vertex count of POSITION, index count), as the extension requires; a stream that does not
// decode, or decodes to something else, is an error naming the primitive.
#include <string>

#include "scene/gltf_accessors.h"
#include "scene/gltf_extension_data.h"
#include "util/error.h"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace penumbra::scene::gltf {

// `uv_attribute`: the TEXCOORD_n the material samples (empty for none).
Result<VertexArrays> decode_draco_primitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                            const DracoPrimitive& draco, const std::string& uv_attribute,
                                            const std::string& file, const std::string& where);

}  // namespace penumbra::scene::gltf
