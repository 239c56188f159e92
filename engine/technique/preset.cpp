#include "technique/preset.h"

#include <filesystem>
#include <set>
#include <string_view>

#include "gl/shader_files.h"
#include "technique/technique.h"
#include "util/file_read.h"

namespace penumbra::technique {

namespace {

// "techniques/baseline/pcss.json" -> "techniques/baseline/presets/pcss."
std::string preset_prefix(const Technique& technique) {
  const std::filesystem::path graph(technique.graph_file);
  return (graph.parent_path() / "presets" / graph.stem()).generic_string() + ".";
}

}  // namespace

std::vector<std::string> shipped_presets(const Technique& technique) {
  const std::string prefix = preset_prefix(technique);
  std::set<std::string> names;
  auto add = [&](std::string_view path) {
    if (path.starts_with(prefix) && path.ends_with(".json") && path.size() > prefix.size() + 5)
      names.emplace(path.substr(prefix.size(), path.size() - prefix.size() - 5));
  };
  for (const gl::EmbeddedShaderFile& f : gl::embedded_shader_files()) add(f.path);
  // A plugin's presets are files beside its graph, not embedded.
  const gl::ShaderFileSystem& files = gl::ShaderFileSystem::default_instance();
  if (auto graph = files.disk_path(technique.graph_file)) {
    std::error_code ec;
    const std::filesystem::path dir = graph->parent_path() / "presets";
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      const std::string file = entry.path().filename().string();
      const std::string stem = std::filesystem::path(technique.graph_file).stem().string() + ".";
      if (file.starts_with(stem) && file.ends_with(".json") && file.size() > stem.size() + 5)
        names.insert(file.substr(stem.size(), file.size() - stem.size() - 5));
    }
  }
  return {names.begin(), names.end()};
}

bool is_preset_path(const std::string& name) { return name.find('/') != std::string::npos || name.ends_with(".json"); }

Result<Preset> load_preset(const Technique& technique, const std::string& name) {
  const bool is_path = is_preset_path(name);
  const std::string file = is_path ? name : preset_prefix(technique) + name + ".json";
  Result<std::string> text = is_path ? read_file_whole(file) : gl::ShaderFileSystem::default_instance().read(file);
  if (!text) {
    if (is_path) return text.error();
    std::string known;
    for (const std::string& n : shipped_presets(technique)) known += (known.empty() ? "" : ", ") + n;
    return make_error("technique '" + technique.name + "' has no preset '" + shortened(name) + "'" +
                      (known.empty() ? std::string(" (it ships none)") : " (shipped: " + known + ")"));
  }
  Result<Preset> preset = parse_preset(*text, file);
  if (preset && preset->technique != technique.name)
    return make_error("preset " + file + " is for technique '" + preset->technique + "', not '" + technique.name + "'");
  return preset;
}

}  // namespace penumbra::technique
