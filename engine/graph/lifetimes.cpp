// Stage: lifetimes of every version in execution order.
#include <algorithm>

#include "graph/compile_state.h"

namespace penumbra::graph::detail {

// Lifetime of a version = [producer's position, last reader's position]; a version read from
// outside the frame starts at 0, one the frame delivers (output / keep alive) ends at
// passes.size(). Extended lifetimes (debug) stretch every version over the whole frame.
void compute_lifetimes(CompileState& s) {
  const int end = static_cast<int>(s.order.size());
  for (VersionState& v : s.versions) {
    v.first_use = v.producer >= 0 ? s.passes[v.producer].order : 0;
    v.last_use = v.first_use;
    for (int reader : v.readers)
      if (!s.passes[reader].culled) v.last_use = std::max(v.last_use, s.passes[reader].order);
    if (v.output) v.last_use = end;
    if (s.options.extended_lifetimes) {
      v.first_use = 0;
      v.last_use = end;
    }
  }
}

}  // namespace penumbra::graph::detail
