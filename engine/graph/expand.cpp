// Stage: expand passes. `enabled` false: the pass is absent (listed as disabled). `repeat` N:
// N consecutive passes "name[0]".."name[N-1]"; because they are consecutive in declaration
// order, iteration i reads the version iteration i-1 wrote (a read_write slot, or in=r/out=r
// ping-pong).
#include "graph/compile_state.h"

namespace penumbra::graph::detail {

void expand_passes(CompileState& s) {
  s.passes.reserve(s.bound.size());
  for (const BoundPass& bp : s.bound) {
    const PassDecl& p = *bp.decl;
    if (!bp.type) continue;  // already reported
    if (!s.holds(p.enabled)) {
      s.disabled.push_back(p.name);
      continue;
    }
    int count = p.repeat_reference.empty() ? p.repeat : s.params.get_int(p.repeat_reference);
    if (count < 1 || count > kMaxRepeat) count = 1;  // already reported
    for (int i = 0; i < count; ++i) {
      ExpandedPass e;
      e.bound = &bp;
      e.name = count == 1 ? p.name : p.name + "[" + std::to_string(i) + "]";
      e.iteration = i;
      e.root = p.side_effect || bp.type->side_effect;
      s.passes.push_back(std::move(e));
    }
  }
}

}  // namespace penumbra::graph::detail
