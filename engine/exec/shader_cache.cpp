#include "exec/shader_cache.h"

#include <spdlog/spdlog.h>

namespace penumbra::exec {

static std::string key_of(const gl::ShaderSources& s) {
  std::string key = s.compute + "|" + s.vertex + "|" + s.fragment;
  for (const auto& [name, value] : s.defines) key += "|" + name + "=" + value;
  return key;
}

gl::ShaderProgram& ShaderCache::get(const gl::ShaderSources& sources) {
  auto& slot = programs_[key_of(sources)];
  if (!slot) {
    slot = std::make_unique<gl::ShaderProgram>(sources, *files_);
    if (Status s = slot->build(); !s) spdlog::error("{}", s.error().to_string());
  }
  return *slot;
}

int ShaderCache::reload_changed() {
  int rebuilt = 0;
  for (auto& [key, program] : programs_) {
    if (!program->sources_changed()) continue;
    ++rebuilt;
    if (Status s = program->reload(); !s)
      spdlog::error("shader reload kept the last good program: {}", s.error().to_string());
    else
      spdlog::info("shader reloaded: {}", key);
  }
  return rebuilt;
}

std::vector<Error> ShaderCache::errors() const {
  std::vector<Error> out;
  for (const auto& [key, program] : programs_)
    if (program->last_error()) out.push_back(*program->last_error());
  return out;
}

}  // namespace penumbra::exec
