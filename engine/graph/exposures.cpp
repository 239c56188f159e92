// Exposed parameters: the graph parameter inherits the pass type's description of the pass
// parameter it exposes, field by field, except the fields it states (its overrides).
#include "graph/exposures.h"

#include <algorithm>
#include <optional>
#include <sstream>

#include "graph/condition.h"

namespace penumbra::graph {

namespace {

std::string range_text(double min, double max) {
  std::ostringstream s;
  s << "[" << min << ", " << max << "]";
  return s.str();
}

class Resolver {
 public:
  Resolver(GraphDesc& graph, const PassTypeRegistry& registry) : graph_(graph), registry_(registry) {}

  GraphErrors run() {
    for (ParamExposure& e : graph_.exposures) resolve(e);
    if (errors_.empty()) check_applies();
    return std::move(errors_);
  }

 private:
  void error(GraphErrorCode code, const ParamExposure& e, std::string message) {
    GraphError err;
    err.code = code;
    err.file = graph_.source_file;
    err.where = e.location.empty() ? "parameter '" + e.parameter + "'" : e.location;
    err.message = "parameter '" + e.parameter + "' exposes '" + e.pass + "." + e.pass_param + "': " + std::move(message);
    errors_.push_back(std::move(err));
  }

  ParamDesc* graph_param(const std::string& name) {
    auto it = std::find_if(graph_.parameters.begin(), graph_.parameters.end(),
                           [&](const ParamDesc& d) { return d.name == name; });
    return it == graph_.parameters.end() ? nullptr : &*it;
  }

  const PassDecl* pass(const std::string& name) const {
    auto it = std::find_if(graph_.passes.begin(), graph_.passes.end(),
                           [&](const PassDecl& p) { return p.name == name; });
    return it == graph_.passes.end() ? nullptr : &*it;
  }

  // The same pass parameter exposed by an earlier parameter: the pass would read two values.
  const ParamExposure* earlier_exposure(const ParamExposure& e) const {
    for (const ParamExposure& other : graph_.exposures) {
      if (&other == &e) return nullptr;
      if (other.pass == e.pass && other.pass_param == e.pass_param) return &other;
    }
    return nullptr;
  }

  void resolve(ParamExposure& e) {
    ParamDesc* d = graph_param(e.parameter);
    if (!d) return;  // the parser records exposures only of parameters it declared
    const PassDecl* p = pass(e.pass);
    if (!p) {
      std::string names;
      for (const PassDecl& q : graph_.passes)
        if (!q.frame) names += (names.empty() ? "" : ", ") + q.name;
      error(GraphErrorCode::unknown_pass, e, "this graph declares no pass '" + e.pass + "'; passes: " +
                                                 (names.empty() ? "(none)" : names));
      return;
    }
    if (p->frame) {
      error(GraphErrorCode::param_shadows_frame, e,
            "pass '" + e.pass + "' is the frame's, whose parameters no technique binds");
      return;
    }
    if (const ParamExposure* twice = earlier_exposure(e)) {
      error(GraphErrorCode::param_bound_twice, e,
            "already exposed by parameter '" + twice->parameter + "' (" + twice->location + ")");
      return;
    }
    const PassTypeDecl* type = registry_.find(p->type);
    if (!type) return;  // compile() names the unknown type with the closest registered ones
    const ParamDesc* from = type->find_param(e.pass_param);
    if (!from) {
      std::string names;
      for (const ParamDesc& q : type->params) names += (names.empty() ? "" : ", ") + q.name;
      error(GraphErrorCode::param_unknown, e, "pass type '" + p->type + "' has no parameter '" + e.pass_param +
                                                  "'; parameters: " + (names.empty() ? "(none)" : names));
      return;
    }
    if (inherit(e, *d, *from)) e.resolved = true;
  }

  // Fills the fields the graph did not state; checks the ones it did. False after an error.
  bool inherit(const ParamExposure& e, ParamDesc& d, const ParamDesc& from) {
    const size_t errors_before = errors_.size();
    auto repeated = [&](const char* field) {
      error(GraphErrorCode::param_described_twice, e,
            std::string("states the ") + field + " that pass type declares already; leave \"" + field + "\" out");
    };
    if (e.stated.type && d.type != from.type) {
      error(GraphErrorCode::param_wrong_type, e, std::string("declared ") + param_type_name(d.type) +
                                                     ", the pass parameter is " + param_type_name(from.type));
      return false;
    }
    d.type = from.type;
    if (d.type == ParamType::real && std::holds_alternative<int>(d.default_value))
      d.default_value = static_cast<double>(std::get<int>(d.default_value));
    if (!e.stated.description) d.description = from.description;
    else if (d.description == from.description) repeated("description");
    if (!e.stated.unit) d.unit = from.unit;
    else if (d.unit == from.unit) repeated("unit");
    else if (!from.unit.empty()) error(GraphErrorCode::param_range_mismatch, e, "unit '" + d.unit + "' is not the pass parameter's '" + from.unit + "'");
    if (!e.stated.options) {
      d.options = from.options;
    } else if (d.options == from.options) {
      repeated("options");
    } else {
      for (const std::string& o : d.options)
        if (std::find(from.options.begin(), from.options.end(), o) == from.options.end())
          error(GraphErrorCode::param_range_mismatch, e, "option \"" + o + "\" is not one the pass type accepts");
    }
    // min and max narrow the pass type's range independently.
    if (!e.stated.min) d.min = from.min;
    else if (d.min == from.min) repeated("min");
    if (!e.stated.max) d.max = from.max;
    else if (d.max == from.max) repeated("max");
    if ((e.stated.min || e.stated.max) && from.has_range() && (d.min < from.min || d.max > from.max || !d.has_range()))
      error(GraphErrorCode::param_range_mismatch, e, "range " + range_text(d.min, d.max) +
                                                         " is wider than the pass type's " + range_text(from.min, from.max));
    if (!e.stated.step) d.step = from.step;
    else if (d.step == from.step) repeated("step");
    if (!e.stated.default_value) {
      if (from.required) {
        error(GraphErrorCode::param_unbound, e, "the pass parameter has no default: state one");
        return false;
      }
      d.default_value = from.default_value;
    } else if (!from.required && d.default_value == from.default_value) {
      repeated("default");
    }
    if (Status s = check_param_value(d, d.default_value); !s)
      error(GraphErrorCode::param_out_of_range, e, "default: " + s.error().message);
    return errors_.size() == errors_before;
  }

  // "applies" and "capped_by" conditions that read an exposing parameter could not be type-checked before its
  // type was known (graph_json.cpp checks the others); all of them are checked here.
  void check_applies() {
    std::vector<ParamDesc> readable = graph_.parameters;
    for (ParamDesc& d : readable) d.structural = true;  // applies may read any parameter
    const ParameterSet params(std::move(readable));
    for (const ParamDesc& d : graph_.parameters)
      for (const auto& [key, text] : d.ui_conditions()) {
        Result<Condition> c = Condition::parse(text);
        std::optional<ConditionProblem> problem =
            c ? c->check(params) : ConditionProblem{ConditionProblem::Kind::syntax, c.error().message};
        if (!problem) continue;
        GraphError err;
        err.code = problem->kind == ConditionProblem::Kind::unknown_parameter ? GraphErrorCode::unknown_param_reference
                                                                             : GraphErrorCode::bad_condition;
        err.file = graph_.source_file;
        err.where = condition_location(d.name, key);
        err.message = "parameter '" + d.name + "': " + problem->message;
        errors_.push_back(std::move(err));
      }
  }

  std::string condition_location(const std::string& name, const std::string& key) const {
    for (const ParamExposure& e : graph_.exposures)
      if (e.parameter == name && e.location.size() > 8) return e.location.substr(0, e.location.size() - 8) + "/" + key;
    return "parameter '" + name + "'";
  }

  GraphDesc& graph_;
  const PassTypeRegistry& registry_;
  GraphErrors errors_;
};

}  // namespace

GraphErrors resolve_exposures(GraphDesc& graph, const PassTypeRegistry& registry) {
  return Resolver(graph, registry).run();
}

}  // namespace penumbra::graph
