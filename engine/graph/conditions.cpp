// Stage: evaluate conditions. Every distinct `enabled` / `when` text of the graph is parsed,
// type-checked and evaluated once for this compile's parameter values; later stages only look
// the value up (CompileState::holds). A bad condition is reported at every place it is used.
#include "graph/compile_state.h"

namespace penumbra::graph::detail {

namespace {

GraphErrorCode code_of(ConditionProblem::Kind kind) {
  switch (kind) {
    case ConditionProblem::Kind::unknown_parameter: return GraphErrorCode::unknown_param_reference;
    case ConditionProblem::Kind::not_structural: return GraphErrorCode::param_not_structural;
    case ConditionProblem::Kind::syntax:
    case ConditionProblem::Kind::wrong_type: return GraphErrorCode::bad_condition;
  }
  return GraphErrorCode::bad_condition;
}

const ConditionState& evaluate(CompileState& s, const std::string& text) {
  auto [it, inserted] = s.conditions.try_emplace(text);
  ConditionState& c = it->second;
  if (!inserted) return c;
  Result<Condition> parsed = Condition::parse(text);
  if (!parsed) {
    c.code = GraphErrorCode::bad_condition;
    c.problem = parsed.error().message;
    return c;
  }
  c.references = parsed->references();
  if (std::optional<ConditionProblem> p = parsed->check(s.params)) {
    c.code = code_of(p->kind);
    c.problem = p->message;
    return c;
  }
  c.valid = true;
  c.holds = parsed->evaluate(s.params);
  return c;
}

void use(CompileState& s, const std::string& text, const std::string& location, const std::string& who) {
  if (text.empty()) return;
  const ConditionState& c = evaluate(s, text);
  if (!c.valid) s.error(c.code, location, who + ": " + c.problem);
}

}  // namespace

void evaluate_conditions(CompileState& s) {
  for (const PassDecl& p : s.graph.passes) {
    bool any = !p.enabled.empty();
    for (const SlotBinding& b : p.slots) any = any || !b.when.empty();
    for (const ParamBinding& b : p.params) any = any || !b.when.empty();
    if (!any) continue;
    const std::string pass_loc = p.location.empty() ? "pass '" + p.name + "'" : p.location;
    use(s, p.enabled, pass_loc + "/enabled", "pass '" + p.name + "'");
    for (const SlotBinding& b : p.slots)
      use(s, b.when, b.location.empty() ? pass_loc : b.location,
          "pass '" + p.name + "', slot '" + b.slot + "'");
    for (const ParamBinding& b : p.params)
      use(s, b.when, b.location.empty() ? pass_loc : b.location,
          "pass '" + p.name + "', parameter '" + b.name + "'");
  }
}

}  // namespace penumbra::graph::detail
