#pragma once
// Every glTF extension Penumbra knows, with what it does about each: the one list the loader
// decides by and docs/gltf.md's table is checked against (tests/docs).
//
//   supported: decoded or applied (geometry, texture coordinates, lights);
//   ignored:   cannot change a shadow (looks, metadata), so a file that requires it still loads,
//              with one warning line naming it;
//   refused:   ignoring it would draw wrong shadows (missing casters, wrong alpha coverage), so
//              a file that requires it is refused with that reason. Only *used* (not required),
//              the file's core data is correct without it, as the glTF spec promises.
// A required extension the table does not know is refused: nothing says ignoring it is safe.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"

namespace penumbra::scene {

enum class GltfExtensionSupport { supported, ignored, refused };

struct GltfExtension {
  std::string_view name;
  GltfExtensionSupport support;
  std::string_view reason;  // what it does here, or why it cannot change a shadow, or why refused
};

std::span<const GltfExtension> gltf_extensions();
const GltfExtension* find_gltf_extension(std::string_view name);

// Refuses the first required extension that is refused or unknown; warns once, naming them, for
// required extensions that are ignored.
Status check_required_gltf_extensions(const std::vector<std::string>& required, const std::string& file);

}  // namespace penumbra::scene
