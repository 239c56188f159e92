#include "technique/technique.h"

#include <algorithm>

#include "gl/shader_files.h"
#include "graph/exposures.h"
#include "graph/graph_json.h"

namespace penumbra::technique {

void TechniqueRegistry::add(Technique technique) {
  for (Technique& t : techniques_)
    if (t.name == technique.name) {
      t = std::move(technique);
      return;
    }
  techniques_.push_back(std::move(technique));
}

bool TechniqueRegistry::remove(const std::string& name) {
  auto it = std::find_if(techniques_.begin(), techniques_.end(), [&](const Technique& t) { return t.name == name; });
  if (it == techniques_.end()) return false;
  techniques_.erase(it);
  return true;
}

const Technique* TechniqueRegistry::find(const std::string& name) const {
  for (const Technique& t : techniques_)
    if (t.name == name) return &t;
  return nullptr;
}

std::vector<std::string> TechniqueRegistry::names() const {
  std::vector<std::string> out;
  for (const Technique& t : techniques_) out.push_back(t.name);
  return out;
}

void TechniqueRegistry::register_passes(exec::PassLibrary& library) const {
  for (const Technique& t : techniques_)
    if (t.register_passes) t.register_passes(library);
}

namespace {

// Bad input (exit 2): the file may be a user's (PENUMBRA_SHADER_DIR, a plugin's folder); the
// built-ins' graphs are compiled by the tests, so one of ours cannot get here unseen.
Error graph_file_error(const graph::GraphErrors& errors) {
  Error e = errors.front();
  std::string all;
  for (const auto& err : errors) all += err.to_string() + "\n";
  e.details = all;
  e.kind = ErrorKind::bad_input;
  return e;
}

}  // namespace

Result<graph::GraphDesc> load_technique_graph(const Technique& technique, const graph::PassTypeRegistry& pass_types) {
  const gl::ShaderFileSystem& files = gl::ShaderFileSystem::default_instance();
  auto text = files.read(technique.graph_file);
  if (!text) return text.error();
  // Errors name the file that was read (a user's override, a plugin's folder), not only its
  // repository path.
  auto on_disk = files.disk_path(technique.graph_file);
  auto graph = graph::parse_graph_json(*text, on_disk ? on_disk->string() : technique.graph_file);
  if (!graph) return graph_file_error(graph.errors());
  if (graph::GraphErrors errors = graph::resolve_exposures(*graph, pass_types); !errors.empty())
    return graph_file_error(errors);
  return std::move(*graph);
}

}  // namespace penumbra::technique
