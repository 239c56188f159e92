#include "sandbox/param_applicability.h"

#include <algorithm>
#include <cmath>

#include "graph/condition.h"

namespace penumbra::sandbox {

namespace {

// "kernel is \"box\", use_blur is false" for the parameters a condition reads.
std::string current_values(const graph::Condition& c, const graph::ParameterSet& params) {
  std::string out;
  for (const std::string& name : c.references()) {
    auto v = params.get(name);
    if (!v) continue;
    out += (out.empty() ? "" : ", ") + name + " is " + graph::param_value_to_string(*v);
  }
  return out;
}

bool planned(const graph::CompiledPlan& plan, const std::string& declared) {
  return std::any_of(plan.passes.begin(), plan.passes.end(),
                     [&](const graph::PlannedPass& p) { return p.declared_as == declared || p.name == declared; });
}

bool listed(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// A UI condition on the current values; nullopt when it cannot be evaluated (the graph loader
// has checked it, so only a per-frame read in a structural-only check ends up here).
std::optional<bool> holds(const std::string& text, const graph::ParameterSet& params) {
  Result<graph::Condition> c = graph::Condition::parse(text);
  const auto problem = c ? c->check(params) : std::nullopt;
  if (!c || (problem && problem->kind != graph::ConditionProblem::Kind::not_structural)) return std::nullopt;
  return c->evaluate(params);
}

// Whether a pass of the plan reads the parameter, and if none does, why not.
Applicability reads_of(const graph::ParamDesc& desc, const graph::GraphDesc& graph, const graph::CompiledPlan& plan) {
  if (desc.structural) return {};
  for (const graph::PlannedPass& p : plan.passes)
    for (const graph::PlannedParam& pp : p.params)
      if (pp.reference == desc.name) return {};

  // Read by no pass of the plan: say which declared passes would read it and why they do not.
  std::string why;
  for (const graph::PassDecl& pass : graph.passes) {
    for (const graph::ParamBinding& b : pass.params) {
      if (b.reference != desc.name) continue;
      std::string one;
      if (listed(plan.disabled, pass.name))
        one = "pass '" + pass.name + "' is disabled (enabled: " + pass.enabled + ")";
      else if (listed(plan.culled, pass.name))
        one = "pass '" + pass.name + "' is culled (none of its outputs reaches the frame)";
      else if (!b.when.empty() && planned(plan, pass.name))
        one = "pass '" + pass.name + "' reads it only when " + b.when;
      if (!one.empty() && why.find(one) == std::string::npos) why += (why.empty() ? "" : "; ") + one;
      break;
    }
  }
  if (why.empty()) {
    // Bound implicitly (by name): the pass that would read it is among the disabled ones.
    why = "no pass of the compiled graph reads it";
    std::string off;
    int listed_passes = 0;
    for (const graph::PassDecl& pass : graph.passes)
      if (listed(plan.disabled, pass.name) && !pass.enabled.empty() && listed_passes++ < 3)
        off += (off.empty() ? "" : ", ") + pass.name + " (enabled: " + pass.enabled + ")";
    if (!off.empty()) why += "; disabled now: " + off;
  }
  return {false, "no effect under the current settings: " + why};
}

std::string cap_note(const graph::ParamDesc& desc, const graph::ParameterSet& params) {
  if (!desc.capped_by || !params.get(desc.capped_by->param)) return "";
  const graph::ParamDesc::Cap& cap = *desc.capped_by;
  if (!cap.when.empty() && holds(cap.when, params) != true) return "";
  return "capped by " + cap.param + " (now " + graph::param_value_to_string(*params.get(cap.param)) + "): " + cap.why;
}

}  // namespace

Applicability param_applicability(const graph::ParamDesc& desc, const graph::ParameterSet& params,
                                  const graph::GraphDesc& graph, const graph::CompiledPlan& plan) {
  if (!desc.applies.empty() && holds(desc.applies, params) == false) {
    const graph::Condition c = *graph::Condition::parse(desc.applies);
    return {false, "no effect unless " + desc.applies + " (now " + current_values(c, params) + ")"};
  }
  Applicability a = reads_of(desc, graph, plan);
  if (a.applies) a.capped = cap_note(desc, params);
  return a;
}

int valid_int_value(const graph::ParamDesc& desc, int value) {
  if (desc.has_range()) value = std::clamp(value, static_cast<int>(std::ceil(desc.min)), static_cast<int>(std::floor(desc.max)));
  if (!desc.has_step()) return value;
  int v = graph::nearest_step_value(desc, value);
  if (desc.has_range() && v > desc.max) v -= desc.step;
  if (desc.has_range() && v < desc.min) v += desc.step;
  return v;
}

}  // namespace penumbra::sandbox
