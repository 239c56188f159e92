#include "gl/shader_files.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace penumbra::gl {

namespace fs = std::filesystem;

ShaderFileSystem::ShaderFileSystem() {
  if (const char* dir = std::getenv("PENUMBRA_SHADER_DIR"); dir && *dir) roots_.emplace_back(dir);
#ifdef PENUMBRA_SOURCE_DIR
  std::error_code ec;
  if (fs::is_directory(PENUMBRA_SOURCE_DIR, ec)) roots_.emplace_back(PENUMBRA_SOURCE_DIR);
#endif
}

ShaderFileSystem::ShaderFileSystem(std::vector<fs::path> roots, bool use_embedded)
    : roots_(std::move(roots)), use_embedded_(use_embedded) {}

ShaderFileSystem& ShaderFileSystem::default_instance() {
  static ShaderFileSystem instance;
  return instance;
}

void ShaderFileSystem::add_root(fs::path root) {
  for (const fs::path& r : roots_)
    if (r == root) return;
  roots_.push_back(std::move(root));
}

std::optional<fs::path> ShaderFileSystem::disk_path(const std::string& path) const {
  std::error_code ec;
  fs::path p(path);
  if (p.is_absolute()) return fs::is_regular_file(p, ec) ? std::optional(p) : std::nullopt;
  for (const fs::path& root : roots_) {
    fs::path candidate = root / p;
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  return std::nullopt;
}

static const EmbeddedShaderFile* find_embedded(const std::string& path) {
  for (const EmbeddedShaderFile& f : embedded_shader_files())
    if (path == f.path) return &f;
  return nullptr;
}

bool ShaderFileSystem::exists(const std::string& path) const {
  return disk_path(path) || (use_embedded_ && find_embedded(path));
}

Result<std::string> ShaderFileSystem::read(const std::string& path) const {
  if (auto p = disk_path(path)) {
    std::ifstream in(*p, std::ios::binary);
    if (!in) {
      Error e = make_error("cannot read shader file");
      e.file = p->string();
      return e;
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  if (use_embedded_) {
    if (const EmbeddedShaderFile* f = find_embedded(path)) return std::string(f->text);
  }
  std::string looked;
  for (const fs::path& root : roots_) looked += (looked.empty() ? "" : ", ") + root.string();
  Error e = make_error("shader file not found (looked in " + (looked.empty() ? "no directory" : looked) +
                       (use_embedded_ ? " and the embedded shaders)" : ")"));
  e.file = path;
  return e;
}

std::optional<fs::file_time_type> ShaderFileSystem::modified(const std::string& path) const {
  auto p = disk_path(path);
  if (!p) return std::nullopt;
  std::error_code ec;
  auto t = fs::last_write_time(*p, ec);
  if (ec) return std::nullopt;
  return t;
}

}  // namespace penumbra::gl
