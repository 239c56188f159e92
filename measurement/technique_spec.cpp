#include "measurement/technique_spec.h"

#include "measurement/eval_capture.h"
#include "technique/preset.h"
#include "passes/shared_passes.h"

namespace penumbra::measurement {

namespace {

std::vector<std::string> split(const std::string& text, char by) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    size_t at = text.find(by, start);
    out.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return out;
    start = at + 1;
  }
}

}  // namespace

Result<std::vector<TechniqueSpec>> parse_technique_specs(const std::string& option, const std::string& text,
                                                         const technique::TechniqueRegistry& registry) {
  auto items = split_list(option, text);
  if (!items) return items.error();
  std::vector<TechniqueSpec> specs;
  for (const std::string& item : *items) {
    std::vector<std::string> parts = split(item, ':');
    const size_t at = parts[0].find('@');
    TechniqueSpec spec{parts[0].substr(0, at), {parts.begin() + 1, parts.end()}, item};
    const technique::Technique* technique = registry.find(spec.name);
    if (!technique) {
      std::string valid;
      for (const std::string& n : registry.names()) valid += (valid.empty() ? "" : ", ") + n;
      return make_error("--" + option + ": unknown technique '" + shortened(spec.name) + "' (available: " + valid + ")");
    }
    auto graph = load_technique_graph(registry, *technique);
    if (!graph) return graph.error();
    graph::ParameterSet params(graph->parameters);
    if (at != std::string::npos) {
      // The preset's errors keep their file, line and column; the item is named before them.
      const std::string preset_name = parts[0].substr(at + 1);
      auto in_item = [&](Error e) {
        e.message = "--" + option + " item '" + shortened(item) + "': " + e.message;
        if (e.file.empty() && technique::is_preset_path(preset_name)) e.file = preset_name;
        return e;
      };
      auto preset = technique::load_preset(*technique, preset_name);
      if (!preset) return in_item(preset.error());
      auto applied = technique::preset_applied(*preset, spec.name, params);
      if (!applied) return in_item(applied.error());
      params = std::move(*applied);
      spec.preset_json = preset->parameters_json;
    }
    if (Status s = graph::check_assignment_keys("--" + option + " item '" + shortened(item) + "'", spec.sets); !s)
      return s.error();
    for (const std::string& kv : spec.sets)
      if (Status s = params.set_from_string(kv); !s)
        return make_error("--" + option + " item '" + shortened(item) + "': " + s.error().message);
    specs.push_back(std::move(spec));
  }
  return specs;
}

std::vector<std::string> technique_names(const std::vector<TechniqueSpec>& specs) {
  std::vector<std::string> names;
  for (const TechniqueSpec& s : specs) names.push_back(s.name);
  return names;
}

Status select_technique(technique::TechniqueSession& session, const TechniqueSpec& spec,
                        const std::vector<std::string>& global_sets) {
  if (Status s = session.set_technique(spec.name); !s) return s;
  if (!spec.preset_json.empty())
    if (Status s = session.apply_preset(spec.preset_json); !s) return s;
  if (Status s = apply_matching_sets(session, global_sets); !s) return s;
  for (const std::string& kv : spec.sets)
    if (Status s = session.set_param(kv); !s) {
      Error e = s.error();
      e.where = spec.label;
      return e;
    }
  return {};
}

}  // namespace penumbra::measurement
