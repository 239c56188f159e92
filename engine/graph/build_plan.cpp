// Stage: build the plan, the executor's view: ordered passes with their chosen bindings,
// parameter values (constants resolved, $-bound ones kept as references read per frame) and
// physical resources.
#include "graph/compile_state.h"

namespace penumbra::graph::detail {

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
    p.type = e.bound->type->name;
    p.name = e.name;
    p.declared_as = e.bound->decl->name;
    p.iteration = e.iteration;
    p.frame = e.bound->decl->frame;
    for (const ResourceUse& u : e.uses) {
      PlannedBinding b;
      b.slot = u.slot->name;
      b.access = u.slot->access;
      b.usage = u.slot->usage;
      b.resource = u.binding->resource;
      if (u.read_version >= 0) b.read_version = s.versions[u.read_version].version;
      if (u.write_version >= 0) b.write_version = s.versions[u.write_version].version;
      b.physical = physical_of_version(u.write_version >= 0 ? u.write_version : u.read_version);
      if (s.graph.resources[u.resource].tile_list) {
        b.tiled_width = s.tiled_width[u.resource];
        b.tiled_height = s.tiled_height[u.resource];
      }
      p.bindings.push_back(std::move(b));
    }
    p.params.reserve(e.bound->params.size());
    for (const BoundParam& bound : e.bound->params) {
      PlannedParam pp;
      pp.name = bound.desc->name;
      if (bound.graph_param) {
        pp.reference = bound.graph_param->name;
        pp.value = *s.params.get(pp.reference);
      } else {
        pp.value = bound.binding ? bound.binding->constant : bound.desc->default_value;
      }
      if (bound.desc->type == ParamType::real && std::holds_alternative<int>(pp.value))
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

}  // namespace penumbra::graph::detail
