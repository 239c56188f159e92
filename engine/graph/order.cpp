// Stage: order passes (stable topological order; a cycle is an error).
#include <functional>
#include <queue>

#include "graph/compile_state.h"

namespace penumbra::graph::detail {

// Stable topological order: among passes whose inputs are ready, the earliest declared runs
// first, so the order is the declaration order whenever the dependencies allow it (what a
// reader of the JSON expects, and "these things tend to be very annoying to debug").
// Edges: producer -> reader of each version; and, for versions sharing one physical resource
// (read_write in place, persistent history), reader of version n -> writer of n+1, and reader of
// version n-1 -> ping-pong writer of n+1 (write-after-read).
void order_passes(CompileState& s) {
  const int n = static_cast<int>(s.passes.size());
  std::vector<std::vector<int>> next(n);
  std::vector<int> indegree(n, 0);
  auto edge = [&](int from, int to) {
    if (from < 0 || from == to || s.passes[from].culled || s.passes[to].culled) return;
    next[from].push_back(to);
    ++indegree[to];
  };
  for (int pi = 0; pi < n; ++pi) {
    if (s.passes[pi].culled) continue;
    for (const ResourceUse& u : s.passes[pi].uses) {
      if (u.read_version >= 0) edge(s.versions[u.read_version].producer, pi);
      if (u.write_version < 0) continue;
      bool shares_physical = u.slot->access == Access::read_write ||
                             s.graph.resources[u.resource].kind == ResourceKind::persistent;
      int prev = shares_physical ? s.existing_version(u.resource, s.versions[u.write_version].version - 1)
                                 : ping_pong_partner(s, u);
      if (prev >= 0)
        for (int reader : s.versions[prev].readers) edge(reader, pi);
    }
  }
  std::priority_queue<int, std::vector<int>, std::greater<int>> ready;
  for (int pi = 0; pi < n; ++pi)
    if (!s.passes[pi].culled && indegree[pi] == 0) ready.push(pi);
  s.order.clear();
  while (!ready.empty()) {
    int pi = ready.top();
    ready.pop();
    s.passes[pi].order = static_cast<int>(s.order.size());
    s.order.push_back(pi);
    for (int to : next[pi])
      if (--indegree[to] == 0) ready.push(to);
  }
  std::string stuck;
  for (int pi = 0; pi < n; ++pi)
    if (!s.passes[pi].culled && s.passes[pi].order < 0)
      stuck += (stuck.empty() ? "'" : ", '") + s.passes[pi].name + "'";
  if (!stuck.empty()) {
    int first = 0;
    while (s.passes[first].culled || s.passes[first].order >= 0) ++first;
    const auto& loc = s.passes[first].bound->decl->location;
    s.error(GraphErrorCode::cycle, loc.empty() ? "pass '" + s.passes[first].name + "'" : loc,
            "cycle between passes " + stuck +
                " (each waits for a version another one writes; check explicit @versions)");
  }
}

}  // namespace penumbra::graph::detail
