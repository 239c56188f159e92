// Stages 8-10: physical resources, the executor's plan, barriers.
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
  Descriptor d{r.kind, r.format, s.width[resource], s.height[resource], r.bytes};
  if (r.kind == ResourceKind::buffer) {
    d.format = Format::R8;
    d.width = d.height = 0;
  } else {
    d.bytes = static_cast<std::uint64_t>(d.width) * d.height * bytes_per_texel(r.format);
  }
  return d;
}

std::uint32_t barrier_bit(Usage u) {
  switch (u) {
    case Usage::sampled: return barrier_texture_fetch;
    case Usage::image_load:
    case Usage::image_store: return barrier_shader_image_access;
    case Usage::color_attachment:
    case Usage::depth_attachment: return barrier_framebuffer;
    case Usage::storage_buffer: return barrier_storage_buffer;
    case Usage::imported: return barrier_none;
  }
  return barrier_none;
}

// Image and SSBO writes are not coherent with later reads in GL; attachment writes are.
bool writes_incoherently(Usage u) {
  return u == Usage::image_store || u == Usage::image_load || u == Usage::storage_buffer;
}

}  // namespace

// Group versions that must share one physical resource (in-place read_write chains; every
// version of a persistent resource), then give each group a physical resource. A transient
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
    for (const ResourceUse& u : s.passes[pi].uses)
      if (u.read_version >= 0 && u.write_version >= 0) unite(u.read_version, u.write_version);

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

void build_plan(CompileState& s) {
  CompiledPlan& plan = s.plan;
  plan.graph_name = s.graph.name;
  plan.settings = s.settings;
  plan.options = s.options;
  plan.outputs = s.graph.outputs;
  plan.disabled = s.disabled;
  auto physical_of_version = [&](int vi) {
    int g = s.versions[vi].group;
    return g < 0 ? -1 : s.groups[g].physical;
  };
  plan.passes.reserve(s.order.size());
  for (int pi : s.order) {
    const ExpandedPass& e = s.passes[pi];
    PlannedPass p;
    p.type = e.type->name;
    p.name = e.name;
    p.declared_as = e.decl->name;
    p.iteration = e.iteration;
    for (const ResourceUse& u : e.uses) {
      PlannedBinding b;
      b.slot = u.slot->name;
      b.access = u.slot->access;
      b.usage = u.slot->usage;
      b.resource = u.binding->resource;
      if (u.read_version >= 0) b.read_version = s.versions[u.read_version].version;
      if (u.write_version >= 0) b.write_version = s.versions[u.write_version].version;
      b.physical = physical_of_version(u.write_version >= 0 ? u.write_version : u.read_version);
      p.bindings.push_back(std::move(b));
    }
    for (const ParamDesc& d : e.type->params) {
      PlannedParam pp;
      pp.name = d.name;
      pp.value = d.default_value;
      for (const ParamBinding& b : e.decl->params) {
        if (b.name != d.name) continue;
        pp.reference = b.reference;
        if (b.reference.empty()) pp.value = b.constant;
        else if (const ParamValue* v = s.params.get(b.reference)) pp.value = *v;
      }
      if (d.type == ParamType::real && std::holds_alternative<int>(pp.value))
        pp.value = static_cast<double>(std::get<int>(pp.value));
      p.params.push_back(std::move(pp));
    }
    plan.passes.push_back(std::move(p));
  }
  for (const ExpandedPass& e : s.passes)
    if (e.culled) plan.culled.push_back(e.name);
  // Versions, grouped by resource in declaration order.
  for (size_t r = 0; r < s.graph.resources.size(); ++r) {
    for (int vi : s.version_of[r]) {
      if (vi < 0 || s.versions[vi].group < 0) continue;
      const VersionState& v = s.versions[vi];
      ResourceVersion out;
      out.name = s.graph.resources[r].name;
      out.version = v.version;
      out.kind = s.graph.resources[r].kind;
      out.physical = physical_of_version(vi);
      out.producer = v.producer >= 0 ? s.passes[v.producer].order : -1;
      out.first_use = v.first_use;
      out.last_use = v.last_use;
      plan.physical_of[out.name] = out.physical;  // ends as the final version's
      plan.versions.push_back(std::move(out));
    }
  }
}

// Before each pass, for every resource it touches whose last writer wrote incoherently
// (image store, SSBO), issue the barrier bit matching THIS pass's usage, once per write.
// Attachment writes followed by sampling need nothing in GL. A persistent resource written
// incoherently starts the frame dirty (last frame's write).
void plan_barriers(CompileState& s) {
  CompiledPlan& plan = s.plan;
  std::vector<char> dirty(plan.physical.size(), 0);
  std::vector<std::uint32_t> issued(plan.physical.size(), 0);
  for (const PlannedPass& p : plan.passes)
    for (const PlannedBinding& b : p.bindings)
      if (b.physical >= 0 && b.write_version >= 0 && writes_incoherently(b.usage) &&
          plan.physical[b.physical].kind == ResourceKind::persistent)
        dirty[b.physical] = 1;
  for (PlannedPass& p : plan.passes) {
    for (const PlannedBinding& b : p.bindings) {
      std::uint32_t bit = barrier_bit(b.usage);
      if (b.physical < 0 || !bit || !dirty[b.physical] || (issued[b.physical] & bit)) continue;
      p.barriers |= bit;
      issued[b.physical] |= bit;
      int v = b.read_version >= 0 ? b.read_version : b.write_version;
      p.barrier_reasons.push_back(b.resource + "@" + std::to_string(v) + ": " +
                                  barrier_bits_to_string(bit));
    }
    for (const PlannedBinding& b : p.bindings) {
      if (b.physical < 0 || b.write_version < 0) continue;
      dirty[b.physical] = writes_incoherently(b.usage);
      issued[b.physical] = 0;
    }
  }
}

}  // namespace penumbra::graph::detail
