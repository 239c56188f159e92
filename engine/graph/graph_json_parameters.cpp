// The graph's "parameters" array: each technique parameter's one declaration (ParamDesc), and
// its `applies` condition checked once all are known.
#include <algorithm>
#include <cmath>
#include <string>

#include "graph/condition.h"
#include "graph/graph_json_reader.h"
#include "graph/json_values.h"

namespace penumbra::graph::json_detail {

void GraphReader::read_parameters(const Json& root, GraphDesc& g) {
  auto it = root.find("parameters");
  if (it == root.end()) return;
  if (!it->is_array()) error(GraphErrorCode::wrong_json_type, "/parameters", "\"parameters\" must be an array");
  else for (size_t i = 0; i < it->size(); ++i) read_parameter((*it)[i], "/parameters/" + std::to_string(i), g);
  check_applies(g);
}

// A parameter is described in full, or exposes a pass parameter ("exposes": "pass.param") and
// states only what it changes; resolve_exposures() (exposures.h) fills in the rest.
void GraphReader::read_parameter(const Json& j, const std::string& ptr, GraphDesc& g) {
  if (!j.is_object()) {
    error(GraphErrorCode::wrong_json_type, ptr, "a parameter must be an object");
    return;
  }
  size_t before = errors_.size();
  ParamDesc d;
  ParamExposure exposure;
  std::string text;
  get_string(j, "name", ptr, d.name, true);
  const bool exposes = j.contains("exposes");
  if (exposes && get_string(j, "exposes", ptr, text, true)) {
    const size_t dot = text.rfind('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == text.size())
      error(GraphErrorCode::wrong_json_type, ptr + "/exposes",
            "\"exposes\" must be \"pass.parameter\", got \"" + shortened(text) + "\"");
    else {
      exposure.pass = text.substr(0, dot);
      exposure.pass_param = text.substr(dot + 1);
    }
  }
  StatedFields& stated = exposure.stated;
  stated = {j.contains("type"),        j.contains("default"), j.contains("min"),     j.contains("max"),
            j.contains("unit"),        j.contains("description"), j.contains("options"), j.contains("step")};
  if (get_string(j, "type", ptr, text, !exposes)) {
    std::optional<ParamType> t = parse_param_type(text);
    if (!t) error(GraphErrorCode::wrong_json_type, ptr + "/type", "type must be bool, int, float or enum, got \"" + shortened(text) + "\"");
    else d.type = *t;
  }
  check_keys(j, ptr, {"name", "type", "default", "min", "max", "step", "unit", "description", "structural", "options",
                      "applies", "capped_by", "exposes"});
  get_string(j, "unit", ptr, d.unit, false);
  get_text(j, "description", ptr, d.description);
  if (auto it = j.find("structural"); it != j.end()) {
    if (it->is_boolean()) d.structural = it->get<bool>();
    else error(GraphErrorCode::wrong_json_type, ptr + "/structural", "\"structural\" must be true or false");
  }
  for (const char* key : {"min", "max"}) {
    auto it = j.find(key);
    if (it == j.end()) continue;
    if (!it->is_number() || !std::isfinite(it->get<double>()))
      error(GraphErrorCode::wrong_json_type, ptr + "/" + key, std::string("\"") + key + "\" must be a finite number");
    else (std::string(key) == "min" ? d.min : d.max) = it->get<double>();
  }
  if (auto it = j.find("step"); it != j.end()) {
    if ((stated.type && d.type != ParamType::integer) || !it->is_number_integer() || it->get<long long>() < 1 ||
        it->get<long long>() > 1000000)
      error(GraphErrorCode::wrong_json_type, ptr + "/step",
            "\"step\" must be an integer in 1..1000000, on an int parameter (valid values: min + k * step)");
    else d.step = it->get<int>();
  }
  get_text(j, "applies", ptr, d.applies);
  if (auto it = j.find("capped_by"); it != j.end()) {
    const std::string cap_ptr = ptr + "/capped_by";
    if (!it->is_object()) {
      error(GraphErrorCode::wrong_json_type, cap_ptr, "\"capped_by\" must be an object {\"param\", \"when\", \"why\"}");
    } else {
      check_keys(*it, cap_ptr, {"param", "when", "why"});
      ParamDesc::Cap cap;
      get_string(*it, "param", cap_ptr, cap.param, true);
      get_text(*it, "when", cap_ptr, cap.when);
      get_string(*it, "why", cap_ptr, cap.why, true);
      d.capped_by = std::move(cap);
    }
  }
  if (auto it = j.find("options"); it != j.end()) {
    if (!it->is_array()) error(GraphErrorCode::wrong_json_type, ptr + "/options", "\"options\" must be an array of strings");
    else
      for (size_t i = 0; i < it->size(); ++i) {
        if ((*it)[i].is_string()) d.options.push_back((*it)[i].get<std::string>());
        else error(GraphErrorCode::wrong_json_type, ptr + "/options/" + std::to_string(i), "option must be a string");
      }
  }
  if (auto it = j.find("default"); it == j.end()) {
    if (!exposes) error(GraphErrorCode::wrong_json_type, ptr, "missing \"default\"");
  } else {
    JsonValue v = json_to_param_value(*it);
    if (!v.ok) error(GraphErrorCode::param_wrong_type, ptr + "/default", v.problem);
    else if (!stated.type) d.default_value = v.value;  // typed and range-checked when resolved
    else if (Status s = check_param_value(d, v.value); !s)
      error(GraphErrorCode::param_out_of_range, ptr + "/default", s.error().message);
    else d.default_value = d.type == ParamType::real && std::holds_alternative<int>(v.value)
                               ? ParamValue{static_cast<double>(std::get<int>(v.value))} : v.value;
  }
  if (errors_.size() != before) return;
  for (const ParamDesc& other : g.parameters)
    if (other.name == d.name) {
      error(GraphErrorCode::duplicate_name, ptr + "/name",
            "parameter '" + shortened(d.name) + "' is declared twice (also at " + param_pointer_[d.name] +
                "); one of them could never be set");
      return;
    }
  param_pointer_[d.name] = ptr;
  if (exposes) {
    exposure.parameter = d.name;
    exposure.location = ptr + "/exposes";
    g.exposures.push_back(std::move(exposure));
  }
  g.parameters.push_back(std::move(d));
}

// "applies" and "capped_by" conditions, once every parameter is known. Unlike `enabled`, they
// may read non-structural parameters: they only tell a UI whether a value has an effect.
void GraphReader::check_applies(const GraphDesc& g) {
  std::vector<ParamDesc> readable = g.parameters;
  for (ParamDesc& d : readable) d.structural = true;  // so check() reports only real problems
  const ParameterSet params(std::move(readable));
  for (const ParamDesc& d : g.parameters) {
    if (d.capped_by && !params.find(d.capped_by->param))
      error(GraphErrorCode::unknown_param_reference, param_pointer_[d.name] + "/capped_by/param",
            "parameter '" + d.name + "' is capped by '" + shortened(d.capped_by->param) + "', which the graph does not declare");
    if (d.capped_by && d.capped_by->param == d.name)
      error(GraphErrorCode::bad_condition, param_pointer_[d.name] + "/capped_by/param",
            "parameter '" + d.name + "' cannot cap itself");
  }
  for (const ParamDesc& d : g.parameters)
    for (const auto& [key, text] : d.ui_conditions()) {
    const std::string where = param_pointer_[d.name] + "/" + key;
    Result<Condition> c = Condition::parse(text);
    if (!c) {
      error(GraphErrorCode::bad_condition, where, "parameter '" + d.name + "': " + c.error().message);
      continue;
    }
    // A parameter whose type comes from the pass it exposes is typed only once resolved:
    // resolve_exposures() checks the conditions that read one.
    const bool reads_untyped = std::any_of(c->references().begin(), c->references().end(), [&](const std::string& r) {
      return std::any_of(g.exposures.begin(), g.exposures.end(),
                         [&](const ParamExposure& e) { return e.parameter == r && !e.stated.type; });
    });
    if (reads_untyped) continue;
    if (std::optional<ConditionProblem> p = c->check(params))
      error(p->kind == ConditionProblem::Kind::unknown_parameter ? GraphErrorCode::unknown_param_reference
                                                                 : GraphErrorCode::bad_condition,
            where, "parameter '" + d.name + "': " + p->message);
    }
}

}  // namespace penumbra::graph::json_detail
