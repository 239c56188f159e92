// Stage: resolve versions. Every chosen binding becomes a read and/or a write of a resource
// version, by the rule in graph_desc.h; a read needs a producer and one version one writer.
#include "graph/compile_state.h"

namespace penumbra::graph::detail {

namespace {

std::string where(const ExpandedPass& pass, const SlotBinding& b) {
  return b.location.empty() ? "pass '" + pass.name + "'" : b.location;
}

}  // namespace

void resolve_versions(CompileState& s) {
  const auto& resources = s.graph.resources;
  // Highest version produced so far per resource, in declaration order; 0 = none yet.
  std::vector<int> highest(resources.size(), 0);
  struct PendingRead {
    int pass;
    const SlotBinding* binding;
    int version;
  };
  std::vector<PendingRead> reads;
  for (int pi = 0; pi < static_cast<int>(s.passes.size()); ++pi) {
    ExpandedPass& pass = s.passes[pi];
    // Reads first (they see the versions before this pass), then writes.
    pass.uses.reserve(pass.bound->slots.size());
    for (const BoundSlot& bs : pass.bound->slots) {
      const SlotBinding* b = bs.binding;
      const SlotDecl* slot = bs.slot;
      const int r = bs.resource;
      if (!slot || r < 0 || b->version > kMaxVersion || b->version < -1) continue;
      ResourceUse use;
      use.slot = slot;
      use.binding = b;
      use.resource = r;
      if (slot->access != Access::write) {
        int v = b->version >= 0 ? b->version : highest[r];
        use.read_version = s.version_index(r, v);
        s.versions[use.read_version].readers.push_back(pi);
        reads.push_back({pi, b, use.read_version});
      }
      pass.uses.push_back(use);
    }
    for (ResourceUse& use : pass.uses) {
      if (use.slot->access == Access::read) continue;
      const SlotBinding& b = *use.binding;
      const int r = use.resource;
      int v = use.slot->access == Access::read_write ? s.versions[use.read_version].version + 1
              : b.version >= 0                       ? b.version
                                                     : highest[r] + 1;
      if (v > kMaxVersion) {
        s.error(GraphErrorCode::version_out_of_range, where(pass, b),
                "pass '" + pass.name + "', slot '" + b.slot + "', resource '" + b.resource +
                    "': this write would make version " + std::to_string(v) + ", past the limit " +
                    std::to_string(kMaxVersion) + " (fewer writes, or a `repeat` count that fits)");
        continue;
      }
      int vi = s.version_index(r, v);
      VersionState& ver = s.versions[vi];
      if (ver.producer >= 0) {
        s.error(GraphErrorCode::two_writers, where(pass, b),
                "pass '" + pass.name + "', slot '" + b.slot + "', resource '" + b.resource + "@" +
                    std::to_string(v) + "': version already written by pass '" +
                    s.passes[ver.producer].name + "'; write a new version instead");
      } else {
        ver.producer = pi;
      }
      use.write_version = vi;
      if (v > highest[r]) highest[r] = v;
      // Writing the output target or history is visible outside the frame.
      ResourceKind k = resources[r].kind;
      if (k == ResourceKind::imported || k == ResourceKind::persistent) pass.root = true;
    }
  }
  // A read needs a producer, except version 0 of what the executor or last frame provides.
  for (const PendingRead& rd : reads) {
    const VersionState& v = s.versions[rd.version];
    ResourceKind k = resources[v.resource].kind;
    bool external = v.version == 0 && (k == ResourceKind::imported || k == ResourceKind::persistent);
    if (v.producer < 0 && !external) {
      const ExpandedPass& p = s.passes[rd.pass];
      s.error(GraphErrorCode::read_without_producer, where(p, *rd.binding),
              "pass '" + p.name + "', slot '" + rd.binding->slot + "', resource '" +
                  rd.binding->resource + "@" + std::to_string(v.version) +
                  "': read with no producer (no enabled pass writes it" +
                  (v.version == 0 ? " before this pass)" : ")"));
    }
  }
}

}  // namespace penumbra::graph::detail
