#pragma once
// Programs shared by all passes, keyed by their sources and defines, built on first use.
// reload_changed() rebuilds the programs whose files changed on disk; a failed rebuild keeps
// the last good program and its error stays visible (errors()) until the file is fixed.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gl/program.h"

namespace penumbra::exec {

class ShaderCache {
 public:
  explicit ShaderCache(const gl::ShaderFileSystem& files = gl::ShaderFileSystem::default_instance())
      : files_(&files) {}
  gl::ShaderProgram& get(const gl::ShaderSources& sources);
  // Returns how many programs were rebuilt.
  int reload_changed();
  // Programs whose latest build failed, with the error (file and line).
  std::vector<Error> errors() const;
  size_t size() const { return programs_.size(); }

 private:
  const gl::ShaderFileSystem* files_;
  std::map<std::string, std::unique_ptr<gl::ShaderProgram>> programs_;
};

}  // namespace penumbra::exec
