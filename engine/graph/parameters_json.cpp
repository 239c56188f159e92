// ParameterSet <-> JSON. One of the few translation units that include nlohmann.
#include <nlohmann/json.hpp>

#include "graph/json_values.h"
#include "graph/parameters.h"
#include "util/json_text.h"

namespace penumbra::graph {

using Json = nlohmann::ordered_json;

Status ParameterSet::apply_json(std::string_view json_text) {
  if (std::optional<JsonTextProblem> p = scan_json_text(json_text)) {
    Error e = make_error("parameter JSON: " + p->message);
    e.line = p->line;
    e.column = p->column;
    return e;
  }
  Json root;
  try {
    root = Json::parse(json_text.begin(), json_text.end());
  } catch (const std::exception& e) {
    return make_error("malformed parameter JSON: " + shortened(e.what(), 200));
  }
  if (!root.is_object()) return make_error("parameter JSON must be an object {\"name\": value}");
  // Validate everything on a copy, then commit: all-or-nothing.
  ParameterSet staged = *this;
  std::string problems;
  for (auto it = root.begin(); it != root.end(); ++it) {
    JsonValue v = json_to_param_value(it.value());
    Status s = v.ok ? staged.set(it.key(), v.value)
                    : Status{make_error("parameter '" + it.key() + "': " + v.problem)};
    if (!s) problems += (problems.empty() ? "" : "; ") + s.error().message;
  }
  if (!problems.empty()) return make_error(problems + " (no parameter was changed)");
  values_ = std::move(staged.values_);
  return {};
}

std::string ParameterSet::to_json() const {
  Json out = Json::object();
  for (size_t i = 0; i < descs_.size(); ++i)
    std::visit([&](const auto& v) { out[descs_[i].name] = v; }, values_[i]);
  return out.dump();
}

}  // namespace penumbra::graph
