#pragma once
// Where shader text comes from. Paths are relative to the repository root
// ("passes/blur/blur.comp.glsl"). Development builds read the source tree first, so an edited
// file is picked up by hot reload; installed or bundled binaries fall back to the copies
// embedded at build time (scripts/cmake/embed_shaders.cmake). PENUMBRA_SHADER_DIR overrides the
// source tree root. A technique plugin's folder is added as a root when it is loaded
// (plugin/plugin_library.h), so its graph JSON and GLSL are read from beside its .so.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "util/error.h"

namespace penumbra::gl {

struct EmbeddedShaderFile {
  const char* path;
  const char* text;
};
const std::vector<EmbeddedShaderFile>& embedded_shader_files();

class ShaderFileSystem {
 public:
  // Roots searched in order on disk; the embedded table comes after them.
  ShaderFileSystem();
  explicit ShaderFileSystem(std::vector<std::filesystem::path> roots, bool use_embedded = true);

  // Tree-wide default: PENUMBRA_SHADER_DIR, then the source tree this binary was built from,
  // then the folders of the plugins loaded so far. Not thread-safe: roots are added while
  // plugins load, before rendering starts.
  static ShaderFileSystem& default_instance();

  // Searched after the roots already there (a plugin's files cannot replace the engine's);
  // a root already present is not added twice.
  void add_root(std::filesystem::path root);
  const std::vector<std::filesystem::path>& roots() const { return roots_; }

  bool exists(const std::string& path) const;
  // The file's text, or an error naming the path and where it was looked for.
  Result<std::string> read(const std::string& path) const;
  // Where `path` is read from on disk; nullopt for embedded-only files.
  std::optional<std::filesystem::path> disk_path(const std::string& path) const;
  // Modification time on disk (hot reload); nullopt for embedded-only files.
  std::optional<std::filesystem::file_time_type> modified(const std::string& path) const;
  // Directories (relative to every root) searched, in order, for an #include that is not found
  // next to the including file: engine/gl/shaders, then passes, so a shader anywhere (a
  // technique, a plugin) writes `#include "common/shadow_common.glsl"` or
  // `"sampling/sampling.glsl"`. The rule is documented once, in docs/writing-a-technique.md.
  const std::vector<std::string>& include_dirs() const { return include_dirs_; }
  void add_include_dir(std::string dir) { include_dirs_.push_back(std::move(dir)); }

 private:
  std::vector<std::filesystem::path> roots_;
  std::vector<std::string> include_dirs_ = {"engine/gl/shaders", "passes"};
  bool use_embedded_ = true;
};

}  // namespace penumbra::gl
