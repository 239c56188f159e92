#pragma once
// The .glb container (glTF 2.0, 4.4 "Binary glTF Layout"): a 12-byte header, a JSON chunk and an
// optional BIN chunk, each chunk 8 bytes of length and type before its data. Split here, checked
// whole (tinygltf 2.7.0 copies a BIN chunk by its stated length without checking it against the
// file), and joined again when the loader rewrites the JSON.
#include <optional>
#include <string>
#include <string_view>

#include "util/error.h"

namespace penumbra::scene::glb {

struct Chunks {
  std::string_view json;
  std::optional<std::string_view> bin;
};

// Every length in the container fits the file, or an error saying which does not. Bytes after
// the length the header states are not part of the container.
Result<Chunks> split(std::string_view bytes, const std::string& file);

// A .glb of these chunks, the JSON padded with spaces to 4 bytes.
std::string join(std::string_view json, std::optional<std::string_view> bin);

}  // namespace penumbra::scene::glb
