#pragma once
// Whether a technique parameter has an effect under the current settings, and why not (GL-free,
// unit-tested). The reason is derived from the graph itself, never from a hand-kept list:
//  - the parameter's own `applies` condition (switches inside one pass), evaluated now;
//  - otherwise, for a parameter read per frame, whether any pass of the compiled plan reads it:
//    one read only by passes that are disabled (their `enabled` condition), culled, or bound to
//    it only under a `when` that does not hold has no effect.
// Structural parameters always apply: they shape the graph. A parameter that applies may still
// be capped by another (its `capped_by`, while its condition holds).
//
//   Applicability a = param_applicability(desc, session.params(), session.graph(), session.plan());
//   if (!a.applies) { ImGui::BeginDisabled(); ... tooltip(a.reason); }
#include <string>

#include "graph/graph_desc.h"
#include "graph/parameters.h"
#include "graph/plan.h"

namespace penumbra::sandbox {

struct Applicability {
  bool applies = true;
  std::string reason;  // why not, naming the condition and the current values; "" when it applies
  // When it applies but another parameter caps its effect now (ParamDesc::capped_by): "capped by
  // NAME (now VALUE): why"; "" otherwise.
  std::string capped;
};

Applicability param_applicability(const graph::ParamDesc& desc, const graph::ParameterSet& params,
                                  const graph::GraphDesc& graph, const graph::CompiledPlan& plan);

// The valid value of an integer parameter nearest `value` within its range and step (an odd-only
// kernel size dragged to 4 becomes 5, past max the largest valid value below it).
int valid_int_value(const graph::ParamDesc& desc, int value);

}  // namespace penumbra::sandbox
