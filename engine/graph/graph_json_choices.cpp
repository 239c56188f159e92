// Choices ({"if"} / {"switch"}): a slot's or parameter's value expanded into bindings under
// `when` conditions, as docs/graph-format.md's "Choices" grammar says (graph_desc.h's binding
// rule: the first applying binding wins). `leaf` turns each plain value into one binding.
#include <string>

#include "graph/condition.h"
#include "graph/graph_json_reader.h"

namespace penumbra::graph::json_detail {

void GraphReader::read_choice(const Json& j, const std::string& ptr, const std::string& when, const GraphDesc& g,
                              const ChoiceLeaf& leaf) {
  if (!j.is_object()) {
    leaf(j, ptr, when);
    return;
  }
  auto negated = [&](const std::string& c) { return condition_and(when, "!(" + c + ")"); };
  if (j.contains("if")) {
    check_keys(j, ptr, {"if", "then", "else"});
    auto cond = j.find("if");
    auto then = j.find("then");
    if (!cond->is_string() || then == j.end()) {
      error(GraphErrorCode::wrong_json_type, ptr, "a choice is {\"if\": \"condition\", \"then\": value, \"else\": value}");
      return;
    }
    const std::string c = cond->get<std::string>();
    read_choice(*then, ptr + "/then", condition_and(when, c), g, leaf);
    if (auto e = j.find("else"); e != j.end()) read_choice(*e, ptr + "/else", negated(c), g, leaf);
    return;
  }
  if (j.contains("switch")) {
    check_keys(j, ptr, {"switch", "cases", "default"});
    auto on = j.find("switch");
    auto cases = j.find("cases");
    if (!on->is_string() || on->get<std::string>().size() < 2 || on->get<std::string>()[0] != '$' ||
        cases == j.end() || !cases->is_object()) {
      error(GraphErrorCode::wrong_json_type, ptr, "a switch is {\"switch\": \"$param\", \"cases\": {\"value\": ...}, \"default\": ...}");
      return;
    }
    const std::string param = on->get<std::string>().substr(1);
    std::string none_matched;
    for (auto c = cases->begin(); c != cases->end(); ++c) {
      std::optional<std::string> cond = case_condition(param, c.key(), ptr + "/cases/" + c.key(), g);
      if (!cond) continue;
      read_choice(c.value(), ptr + "/cases/" + c.key(), condition_and(when, *cond), g, leaf);
      none_matched = condition_and(none_matched, "!(" + *cond + ")");
    }
    if (auto d = j.find("default"); d != j.end()) read_choice(*d, ptr + "/default", condition_and(when, none_matched), g, leaf);
    return;
  }
  error(GraphErrorCode::wrong_json_type, ptr,
        "expected a value, or a choice {\"if\": ...} / {\"switch\": ...}");
}

// The condition text a `switch` case stands for: `$p == "case"` for an enum (or a string),
// `$p == 3` for an int, `$p == true` for a bool, by the parameter's declared type.
std::optional<std::string> GraphReader::case_condition(const std::string& param, const std::string& value,
                                                       const std::string& ptr, const GraphDesc& g) {
  for (const ParamDesc& d : g.parameters) {
    if (d.name != param) continue;
    if (d.type == ParamType::integer) {
      bool digits = !value.empty() && value.find_first_not_of("-0123456789") == std::string::npos && value.size() < 11;
      if (digits) return "$" + param + " == " + value;
    } else if (d.type == ParamType::boolean) {
      if (value == "true" || value == "false") return "$" + param + " == " + value;
    } else if (value.find('"') == std::string::npos) {
      return "$" + param + " == \"" + value + "\"";
    }
    error(GraphErrorCode::bad_condition, ptr,
          "case \"" + shortened(value) + "\" is not a value of '$" + param + "' (" + param_type_name(d.type) + ")");
    return std::nullopt;
  }
  error(GraphErrorCode::unknown_param_reference, ptr, "switch on '$" + shortened(param) + "', which is not a parameter of this graph");
  return std::nullopt;
}

}  // namespace penumbra::graph::json_detail
