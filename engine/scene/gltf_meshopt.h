#pragma once
// EXT_meshopt_compression: every compressed bufferView decoded into its own range of its buffer
// (a fallback buffer is created at its declared size first), so accessors then read plain data.
// Each stream's parameters are checked against what libmeshoptimizer asserts on before it is
// called, and a stream that does not decode is an error naming the bufferView.
#include <string>

#include "scene/gltf_extension_data.h"
#include "util/error.h"

namespace tinygltf {
class Model;
}

namespace penumbra::scene::gltf {

Status decode_meshopt_views(tinygltf::Model& model, const ExtensionData& extensions, const std::string& file);

}  // namespace penumbra::scene::gltf
