// Stage: assign physical resources (whole textures reused between identical descriptors).
#include <algorithm>
#include <numeric>

#include "graph/compile_state.h"

namespace penumbra::graph::detail {

namespace {

bool is_live(const CompileState& s, const VersionState& v) {
  if (v.producer >= 0 && !s.passes[v.producer].culled) return true;
  for (int r : v.readers)
    if (!s.passes[r].culled) return true;
  return false;
}

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// The descriptor a physical resource is created from; reuse needs it to be IDENTICAL.
struct Descriptor {
  ResourceKind kind;
  Format format;
  int width, height;
  std::uint64_t bytes;
  bool operator==(const Descriptor&) const = default;
};

Descriptor descriptor_of(const CompileState& s, int resource) {
  const ResourceDecl& r = s.graph.resources[resource];
  Descriptor d{r.kind, r.format, s.width[resource], s.height[resource], s.bytes[resource]};
  if (r.kind == ResourceKind::buffer) {
    d.format = Format::R8;
    d.width = d.height = 0;
  } else {
    d.bytes = static_cast<std::uint64_t>(d.width) * d.height * bytes_per_texel(r.format);
  }
  return d;
}

}  // namespace

// Group versions that must share one physical resource (in-place read_write chains; ping-pong
// writes with the version two back; every version of a persistent resource), then give each group a physical resource. A transient
// group reuses a physical resource only when the descriptor (kind, format, resolved size,
// bytes) is identical and its lifetime starts after the previous holder's last use: GL 4.5
// has no memory aliasing, so whole textures are recycled. Persistent groups never share;
// imported ones get none. Groups are visited by first use, ties by creation, so the result
// is deterministic.
void assign_physical_resources(CompileState& s) {
  const int nv = static_cast<int>(s.versions.size());
  std::vector<int> parent(nv);
  std::iota(parent.begin(), parent.end(), 0);
  auto unite = [&](int a, int b) { parent[find_root(parent, a)] = find_root(parent, b); };
  std::vector<int> first_of_resource(s.graph.resources.size(), -1);
  for (int vi = 0; vi < nv; ++vi) {
    const VersionState& v = s.versions[vi];
    if (!is_live(s, v)) continue;
    if (s.graph.resources[v.resource].kind == ResourceKind::persistent) {
      if (first_of_resource[v.resource] < 0) first_of_resource[v.resource] = vi;
      else unite(vi, first_of_resource[v.resource]);
    }
  }
  for (int pi : s.order)
    for (const ResourceUse& u : s.passes[pi].uses) {
      if (u.read_version >= 0 && u.write_version >= 0) unite(u.read_version, u.write_version);
      if (int back = ping_pong_partner(s, u); back >= 0) unite(u.write_version, back);
    }

  std::vector<int> group_of_root(nv, -1);
  for (int vi = 0; vi < nv; ++vi) {
    VersionState& v = s.versions[vi];
    if (!is_live(s, v)) continue;
    int root = find_root(parent, vi);
    if (group_of_root[root] < 0) {
      group_of_root[root] = static_cast<int>(s.groups.size());
      s.groups.push_back({v.resource, v.first_use, v.last_use, -1, {}});
    }
    VersionGroup& g = s.groups[group_of_root[root]];
    g.first_use = std::min(g.first_use, v.first_use);
    g.last_use = std::max(g.last_use, v.last_use);
    g.versions.push_back(vi);
    v.group = group_of_root[root];
  }

  std::vector<int> by_first(s.groups.size());
  std::iota(by_first.begin(), by_first.end(), 0);
  std::stable_sort(by_first.begin(), by_first.end(),
                   [&](int a, int b) { return s.groups[a].first_use < s.groups[b].first_use; });
  std::vector<Descriptor> desc_of_physical;
  std::vector<int> busy_until;  // last use of the physical resource's current holder
  for (int gi : by_first) {
    VersionGroup& g = s.groups[gi];
    const ResourceKind kind = s.graph.resources[g.resource].kind;
    if (kind == ResourceKind::imported) continue;
    Descriptor d = descriptor_of(s, g.resource);
    s.plan.memory.naive_bytes += d.bytes;
    if (kind != ResourceKind::persistent && !s.options.no_reuse) {
      for (size_t p = 0; p < desc_of_physical.size(); ++p) {
        if (busy_until[p] < g.first_use && desc_of_physical[p] == d &&
            s.plan.physical[p].kind != ResourceKind::persistent) {
          g.physical = static_cast<int>(p);
          break;
        }
      }
    }
    if (g.physical < 0) {
      g.physical = static_cast<int>(s.plan.physical.size());
      PhysicalResource phys;
      phys.id = g.physical;
      phys.kind = kind;
      phys.format = d.format;
      phys.width = d.width;
      phys.height = d.height;
      phys.bytes = d.bytes;
      s.plan.physical.push_back(std::move(phys));
      desc_of_physical.push_back(d);
      busy_until.push_back(-1);
      s.plan.memory.assigned_bytes += d.bytes;
    }
    busy_until[g.physical] = g.last_use;
    for (int vi : g.versions)
      s.plan.physical[g.physical].holds.push_back(
          s.graph.resources[g.resource].name + "@" + std::to_string(s.versions[vi].version));
  }
}

}  // namespace penumbra::graph::detail
