// Stages 3-4: expand declarations into the passes that exist for these parameter values, and
// resolve every binding to a resource version (the rule is in graph_desc.h).
#include "graph/compile_state.h"
#include "graph/condition.h"

namespace penumbra::graph::detail {

// `enabled` false: the pass is absent (listed as disabled). `repeat` N: N consecutive passes
// "name[0]".."name[N-1]"; because they are consecutive in declaration order, iteration i
// reads the version iteration i-1 wrote (a read_write slot, or in=r/out=r ping-pong).
void expand_passes(CompileState& s) {
  s.passes.reserve(s.graph.passes.size());
  for (const PassDecl& p : s.graph.passes) {
    const PassTypeDecl* type = s.registry.find(p.type);
    if (!type) continue;  // already reported
    if (!p.enabled.empty()) {
      Result<Condition> c = Condition::parse(p.enabled);
      if (c && c->check(s.params) && !c->evaluate(s.params)) {
        s.disabled.push_back(p.name);
        continue;
      }
    }
    int count = p.repeat_reference.empty() ? p.repeat : s.params.get_int(p.repeat_reference);
    if (count < 1 || count > kMaxRepeat) count = 1;  // already reported
    for (int i = 0; i < count; ++i) {
      ExpandedPass e;
      e.decl = &p;
      e.type = type;
      e.name = count == 1 ? p.name : p.name + "[" + std::to_string(i) + "]";
      e.iteration = i;
      e.root = p.side_effect || type->side_effect;
      s.passes.push_back(std::move(e));
    }
  }
}

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
    for (int phase = 0; phase < 2; ++phase) {
      for (const SlotBinding& b : pass.decl->slots) {
        const SlotDecl* slot = pass.type->find_slot(b.slot);
        int r = s.find_resource(b.resource);
        if (!slot || r < 0 || b.version > kMaxVersion || b.version < -1) continue;
        bool reads_it = slot->access != Access::write;
        bool writes_it = slot->access != Access::read;
        if (phase == 0) {
          ResourceUse use;
          use.slot = slot;
          use.binding = &b;
          use.resource = r;
          if (reads_it) {
            int v = b.version >= 0 ? b.version : highest[r];
            use.read_version = s.version_index(r, v);
            s.versions[use.read_version].readers.push_back(pi);
            reads.push_back({pi, &b, use.read_version});
          }
          pass.uses.push_back(use);
        } else if (writes_it) {
          ResourceUse* use = nullptr;
          for (auto& u : pass.uses)
            if (u.binding == &b) use = &u;
          int v;
          if (slot->access == Access::read_write)
            v = s.versions[use->read_version].version + 1;
          else
            v = b.version >= 0 ? b.version : highest[r] + 1;
          if (v > kMaxVersion) continue;
          int vi = s.version_index(r, v);
          VersionState& ver = s.versions[vi];
          if (ver.producer >= 0) {
            s.error(GraphErrorCode::two_writers, b.location.empty() ? "pass '" + pass.name + "'" : b.location,
                    "pass '" + pass.name + "', slot '" + b.slot + "', resource '" +
                        b.resource + "@" + std::to_string(v) + "': version already written by pass '" +
                        s.passes[ver.producer].name + "'; write a new version instead");
          } else {
            ver.producer = pi;
          }
          use->write_version = vi;
          if (v > highest[r]) highest[r] = v;
          // Writing the output target or history is visible outside the frame.
          ResourceKind k = resources[r].kind;
          if (k == ResourceKind::imported || k == ResourceKind::persistent) pass.root = true;
        }
      }
    }
  }
  // A read needs a producer, except version 0 of what the executor or last frame provides.
  for (const PendingRead& rd : reads) {
    const VersionState& v = s.versions[rd.version];
    ResourceKind k = resources[v.resource].kind;
    bool external = v.version == 0 && (k == ResourceKind::imported || k == ResourceKind::persistent);
    if (v.producer < 0 && !external) {
      const ExpandedPass& p = s.passes[rd.pass];
      s.error(GraphErrorCode::read_without_producer,
              rd.binding->location.empty() ? "pass '" + p.name + "'" : rd.binding->location,
              "pass '" + p.name + "', slot '" + rd.binding->slot + "', resource '" +
                  rd.binding->resource + "@" + std::to_string(v.version) +
                  "': read with no producer (no enabled pass writes it" +
                  (v.version == 0 ? " before this pass)" : ")"));
    }
  }
}

}  // namespace penumbra::graph::detail
