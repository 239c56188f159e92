// Stages 5-7: cull, order, lifetimes.
#include <algorithm>
#include <functional>
#include <queue>

#include "graph/compile_state.h"

namespace penumbra::graph::detail {

namespace {
// Versions the frame must deliver: the final version of each output and of each resource the
// viewer asked to keep alive.
void mark_frame_results(CompileState& s) {
  auto mark_final = [&](std::string_view name, bool all_versions) {
    int r = s.find_resource(name);
    if (r < 0) return;
    const auto& slots = s.version_of[r];
    for (int v = static_cast<int>(slots.size()) - 1; v >= 0; --v) {
      if (slots[v] < 0 || s.versions[slots[v]].producer < 0) continue;
      s.versions[slots[v]].output = true;
      if (!all_versions) return;
    }
  };
  for (const auto& name : s.graph.outputs) mark_final(name, false);
  for (const auto& name : s.options.keep_alive) mark_final(name, true);
}
}  // namespace

// -- Culling: reference-count flood fill (skaarj1989/FrameGraph). A version's refcount is its
// number of readers (+1 if the frame must deliver it); a pass's refcount is the number of its
// written versions still referenced (+1 for side effects). Versions at zero release their
// producer; a producer at zero is culled and releases the versions it reads.
void cull_passes(CompileState& s) {
  mark_frame_results(s);
  std::vector<int> pass_refs(s.passes.size(), 0);
  for (size_t pi = 0; pi < s.passes.size(); ++pi) {
    for (const ResourceUse& u : s.passes[pi].uses)
      if (u.write_version >= 0) ++pass_refs[pi];
    if (s.passes[pi].root) ++pass_refs[pi];
  }
  std::vector<int> unreferenced;
  for (size_t vi = 0; vi < s.versions.size(); ++vi) {
    VersionState& v = s.versions[vi];
    v.refcount = static_cast<int>(v.readers.size()) + (v.output ? 1 : 0);
    if (v.refcount == 0) unreferenced.push_back(static_cast<int>(vi));
  }
  while (!unreferenced.empty()) {
    const VersionState& v = s.versions[unreferenced.back()];
    unreferenced.pop_back();
    if (v.producer < 0) continue;
    ExpandedPass& producer = s.passes[v.producer];
    if (--pass_refs[v.producer] > 0) continue;
    producer.culled = true;
    for (const ResourceUse& u : producer.uses)
      if (u.read_version >= 0 && --s.versions[u.read_version].refcount == 0)
        unreferenced.push_back(u.read_version);
  }
}

// Stable topological order: among passes whose inputs are ready, the earliest declared runs
// first, so the order is the declaration order whenever the dependencies allow it (what a
// reader of the JSON expects, and "these things tend to be very annoying to debug").
// Edges: producer -> reader of each version; and, for versions sharing one physical resource
// (read_write in place, persistent history), reader of version n -> writer of n+1
// (write-after-read).
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
      if (!shares_physical) continue;
      int prev = s.existing_version(u.resource, s.versions[u.write_version].version - 1);
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
    const auto& loc = s.passes[first].decl->location;
    s.error(GraphErrorCode::cycle, loc.empty() ? "pass '" + s.passes[first].name + "'" : loc,
            "cycle between passes " + stuck +
                " (each waits for a version another one writes; check explicit @versions)");
  }
}

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
