// Stage (before the others): the format of each resource whose format structural parameters
// choose, for this compile's values. The graph is copied only when some resource chooses.
#include <algorithm>

#include "graph/compile_state.h"
#include "graph/condition.h"

namespace penumbra::graph::detail {

std::optional<GraphDesc> choose_formats(const GraphDesc& graph, const ParameterSet& params, GraphErrors& errors) {
  const bool any = std::any_of(graph.resources.begin(), graph.resources.end(),
                               [](const ResourceDecl& r) { return !r.format_choices.empty(); });
  if (!any) return std::nullopt;
  GraphDesc chosen = graph;
  for (ResourceDecl& r : chosen.resources) {
    if (r.format_choices.empty()) continue;
    const std::string at = (r.location.empty() ? "resource '" + r.name + "'" : r.location) + "/format";
    bool failed = false;
    auto fail = [&](GraphErrorCode code, std::string message) {
      failed = true;
      GraphError e;
      e.code = code;
      e.file = graph.source_file;
      e.where = at;
      e.message = "resource '" + r.name + "': " + std::move(message);
      errors.push_back(std::move(e));
    };
    bool found = false;
    for (const FormatChoice& c : r.format_choices) {
      Result<Condition> condition = Condition::parse(c.when);
      if (!condition) {
        fail(GraphErrorCode::bad_condition, condition.error().message);
        break;
      }
      if (std::optional<ConditionProblem> p = condition->check(params)) {
        // The format decides the texture's descriptor: only a structural (recompiling)
        // parameter may choose it.
        fail(p->kind == ConditionProblem::Kind::not_structural ? GraphErrorCode::param_not_structural
             : p->kind == ConditionProblem::Kind::unknown_parameter ? GraphErrorCode::unknown_param_reference
                                                                    : GraphErrorCode::bad_condition,
             p->message);
        break;
      }
      if (condition->evaluate(params)) {
        r.format = c.format;
        found = true;
        break;
      }
    }
    if (!found && !failed)
      fail(GraphErrorCode::bad_condition, "no case of its format applies to these parameters (add a \"default\")");
  }
  return chosen;
}

}  // namespace penumbra::graph::detail
