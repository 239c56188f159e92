// Part of the validate stage: the checks on the graph's parameters that no single pass shows.
// A parameter must reach the graph in some variant (a pass parameter, a condition, a size or a
// repeat count): one that reaches nothing is a slider that does nothing, the bug binding by
// name used to hide. Exposures must have been resolved against the pass types, and no graph
// parameter may take the name of a parameter of the frame's own passes.
#include <set>

#include "graph/compile_state.h"
#include "graph/condition.h"

namespace penumbra::graph::detail {

namespace {

// Every graph parameter some declaration reads, whatever the variant: bindings and conditions
// of every branch, repeat counts, texture sizes, exposures. `applies` is not a read: it only
// tells a UI when a value matters.
std::set<std::string, std::less<>> reached_parameters(const CompileState& s) {
  std::set<std::string, std::less<>> reached;
  auto condition = [&](const std::string& text) {
    if (text.empty()) return;
    if (auto it = s.conditions.find(text); it != s.conditions.end())
      reached.insert(it->second.references.begin(), it->second.references.end());
  };
  for (const PassDecl& p : s.graph.passes) {
    condition(p.enabled);
    if (!p.repeat_reference.empty()) reached.insert(p.repeat_reference);
    for (const SlotBinding& b : p.slots) condition(b.when);
    for (const ParamBinding& b : p.params) {
      condition(b.when);
      if (!b.reference.empty()) reached.insert(b.reference);
    }
  }
  for (const ResourceDecl& r : s.graph.resources) {
    if (!r.size.divisor_reference.empty()) reached.insert(r.size.divisor_reference);
    for (const FormatChoice& c : r.format_choices)
      if (Result<Condition> parsed = Condition::parse(c.when))
        reached.insert(parsed->references().begin(), parsed->references().end());
  }
  for (const ParamExposure& e : s.graph.exposures) reached.insert(e.parameter);
  return reached;
}

void validate_exposures(CompileState& s) {
  for (const ParamExposure& e : s.graph.exposures) {
    if (e.resolved) continue;
    s.error(GraphErrorCode::exposure_unresolved, e.location.empty() ? param_location(s, e.parameter) : e.location,
            "parameter '" + e.parameter + "' exposes '" + e.pass + "." + e.pass_param +
                "', which was not resolved against the pass types (graph/exposures.h: resolve_exposures)");
  }
}

void validate_frame_names(CompileState& s) {
  for (const PassDecl& p : s.graph.passes) {
    if (!p.frame) continue;
    const PassTypeDecl* type = s.registry.find(p.type);
    if (!type) continue;
    for (const ParamDesc& frame_param : type->params)
      if (s.params.find(frame_param.name))
        s.error(GraphErrorCode::param_shadows_frame, param_location(s, frame_param.name),
                "parameter '" + frame_param.name + "' has the name of a parameter of the frame's pass '" + p.name +
                    "' (type " + p.type + ", frame_graph.h); a technique parameter cannot set the frame's: "
                    "rename it");
  }
}

}  // namespace

void validate_parameter_graph(CompileState& s) {
  validate_exposures(s);
  validate_frame_names(s);
  const auto reached = reached_parameters(s);
  for (const ParamDesc& d : s.graph.parameters)
    if (!reached.count(d.name))
      s.error(GraphErrorCode::param_unreached, param_location(s, d.name),
              "parameter '" + d.name + "' reaches nothing in any variant: no pass binds or exposes it and no "
              "condition, size or repeat reads it");
}

}  // namespace penumbra::graph::detail
