// "templates" and `extends`, the one way passes share what they bind: a template is read once
// where it is declared, with a pass's rules, into the PassShape it gives; a pass extending
// templates starts from their shapes merged in order. The grammar is docs/graph-format.md's
// "Templates" section.
#include "graph/condition.h"
#include "graph/graph_json_reader.h"

namespace penumbra::graph::json_detail {

void GraphReader::read_templates(const Json& root) {
  auto it = root.find("templates");
  if (it == root.end()) return;
  if (!it->is_object()) {
    error(GraphErrorCode::wrong_json_type, "/templates", "\"templates\" must be an object {name: {\"slots\": ..., \"params\": ...}}");
    return;
  }
  for (auto t = it->begin(); t != it->end(); ++t) {
    const std::string ptr = "/templates/" + t.key();
    if (!t->is_object()) {
      error(GraphErrorCode::wrong_json_type, ptr, "a template must be an object");
      continue;
    }
    check_keys(*t, ptr, {"type", "enabled", "slots", "params", "description"});
    PassShape shape;
    if (std::string type; get_string(*t, "type", ptr, type, false)) shape.type = std::move(type);
    get_enabled(*t, ptr, shape.enabled);
    collect(*t, "slots", ptr, shape.slots);
    collect(*t, "params", ptr, shape.params);
    templates_[t.key()] = std::move(shape);
  }
}

PassShape GraphReader::extended_shape(const Json& pass, const std::string& ptr) {
  PassShape shape;
  auto it = pass.find("extends");
  if (it == pass.end()) return shape;
  std::vector<Json> names = it->is_array() ? it->get<std::vector<Json>>() : std::vector<Json>{*it};
  for (const Json& n : names) {
    if (!n.is_string()) {
      error(GraphErrorCode::wrong_json_type, ptr + "/extends", "\"extends\" must be a template name or an array of them");
      continue;
    }
    auto t = templates_.find(n.get<std::string>());
    if (t == templates_.end()) {
      std::string known;
      for (const auto& [name, unused] : templates_) known += (known.empty() ? "" : ", ") + name;
      error(GraphErrorCode::wrong_json_type, ptr + "/extends",
            "no template named '" + shortened(n.get<std::string>()) + "'; templates: " + (known.empty() ? "(none)" : known));
      continue;
    }
    const PassShape& later = t->second;
    if (later.type) shape.type = later.type;
    shape.enabled = condition_and(shape.enabled, later.enabled);
    shape.slots.merge(later.slots);
    shape.params.merge(later.params);
  }
  return shape;
}

}  // namespace penumbra::graph::json_detail
