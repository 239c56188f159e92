// Stage: bind passes. For every declared pass, the bindings that apply for this compile's
// parameter values (graph_desc.h's binding rule): per slot the first binding whose `when`
// holds; per pass-type parameter the first applying binding, else the graph parameter of the
// same name (implicit binding), else the type's default. Validation checks what this chose.
#include <algorithm>

#include "graph/compile_state.h"

namespace penumbra::graph::detail {

namespace {

// Chosen bindings in the pass type's slot order, so a plan does not depend on the order a file
// (or a template and the pass extending it) lists the slots in.
void bind_slots(const CompileState& s, const PassDecl& p, BoundPass& out) {
  std::vector<std::string_view> decided;
  for (const SlotBinding& b : p.slots) {
    if (std::find(decided.begin(), decided.end(), b.slot) != decided.end()) continue;
    if (!s.holds(b.when)) continue;
    decided.push_back(b.slot);
    if (!b.resource.empty()) out.slots.push_back(&b);
  }
  if (!out.type) return;
  auto rank = [&](const SlotBinding* b) {
    const auto& slots = out.type->slots;
    for (size_t i = 0; i < slots.size(); ++i)
      if (slots[i].name == b->slot) return i;
    return slots.size();
  };
  std::stable_sort(out.slots.begin(), out.slots.end(),
                   [&](const SlotBinding* a, const SlotBinding* b) { return rank(a) < rank(b); });
}

void bind_params(const CompileState& s, const PassDecl& p, BoundPass& out) {
  out.params.reserve(out.type->params.size());
  for (const ParamDesc& d : out.type->params) {
    BoundParam bp;
    bp.desc = &d;
    const ParamBinding* chosen = nullptr;
    for (const ParamBinding& b : p.params)
      if (b.name == d.name && s.holds(b.when)) {
        chosen = &b;
        break;
      }
    if (chosen && !chosen->unbound) {
      bp.binding = chosen;
      if (!chosen->reference.empty()) bp.graph_param = s.params.find(chosen->reference);
    } else {
      bp.graph_param = s.params.find(d.name);
    }
    out.params.push_back(bp);
  }
}

}  // namespace

void bind_passes(CompileState& s) {
  s.bound.resize(s.graph.passes.size());
  for (size_t i = 0; i < s.graph.passes.size(); ++i) {
    const PassDecl& p = s.graph.passes[i];
    BoundPass& b = s.bound[i];
    b.decl = &p;
    b.type = s.registry.find(p.type);
    bind_slots(s, p, b);
    if (b.type) bind_params(s, p, b);
  }
}

}  // namespace penumbra::graph::detail
