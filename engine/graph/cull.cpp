// Stage: cull passes whose results reach no output, side effect or kept-alive resource.
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

}  // namespace penumbra::graph::detail
