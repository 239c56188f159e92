// Stage: bind passes. For every declared pass, the bindings that apply for this compile's
// parameter values (graph_desc.h's binding rule): per slot the first binding whose `when`
// holds; per pass-type parameter the first applying binding, else the graph parameter exposing
// it, else the type's default. Nothing binds by name. Validation checks what this chose.
#include <algorithm>

#include "graph/compile_state.h"

namespace penumbra::graph::detail {

namespace {

// Every declared slot binding with its lookups; the applying ones in the pass type's slot
// order, so a plan does not depend on the order a file (or a template and the pass extending
// it) lists the slots in.
void bind_slots(const CompileState& s, const PassDecl& p, BoundPass& out) {
  out.declared.reserve(p.slots.size());
  for (const SlotBinding& b : p.slots) {
    BoundSlot bs;
    bs.binding = &b;
    bs.slot = out.type ? out.type->find_slot(b.slot) : nullptr;
    bs.resource = b.resource.empty() ? -1 : s.find_resource(b.resource);
    bool decided = std::any_of(out.declared.begin(), out.declared.end(), [&](const BoundSlot& earlier) {
      return earlier.applies && earlier.binding->slot == b.slot;
    });
    bs.applies = !decided && s.holds(b.when);
    out.declared.push_back(bs);
  }
  if (!out.type) return;
  const SlotDecl* first = out.type->slots.data();
  out.slots.reserve(out.declared.size());
  for (const BoundSlot& bs : out.declared)
    if (bs.applies && !bs.binding->resource.empty()) {
      // Insertion in slot order (a pass has a handful of slots); unknown slots go last.
      auto rank = [&](const BoundSlot& x) { return x.slot ? x.slot - first : out.type->slots.end() - out.type->slots.begin(); };
      auto at = std::upper_bound(out.slots.begin(), out.slots.end(), bs,
                                 [&](const BoundSlot& a, const BoundSlot& b) { return rank(a) < rank(b); });
      out.slots.insert(at, bs);
    }
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
      for (const ParamExposure& e : s.graph.exposures)
        if (e.pass == p.name && e.pass_param == d.name) {
          bp.exposure = &e;
          bp.graph_param = s.params.find(e.parameter);
          break;
        }
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
