// Stage: index resources. Names become indices once, and every texture's size is resolved
// from the compile settings (screen, shadow) and, for `screen/$param`, the parameter's value.
#include "graph/compile_state.h"

namespace penumbra::graph::detail {

namespace {

std::string where_of(const ResourceDecl& r) {
  return r.location.empty() ? "resource '" + r.name + "'" : r.location;
}

// The divisor a size expression divides by; reports a reference that cannot be one (it must
// be a structural int parameter whose whole range is a valid divisor, so every value a user
// can set compiles).
int divisor_of(CompileState& s, const ResourceDecl& r) {
  const std::string& name = r.size.divisor_reference;
  if (name.empty()) return r.size.divisor;
  const std::string who = "resource '" + r.name + "': size '" + r.size.to_string() + "'";
  const ParamDesc* d = s.params.find(name);
  if (!d) {
    s.error(GraphErrorCode::unknown_param_reference, where_of(r) + "/size",
            who + ": '$" + name + "' is not a parameter of graph '" + s.graph.name + "'");
    return 1;
  }
  if (d->type != ParamType::integer) {
    s.error(GraphErrorCode::param_wrong_type, where_of(r) + "/size",
            who + ": '$" + name + "' must be an int parameter, is " + param_type_name(d->type));
    return 1;
  }
  if (!d->structural) {
    s.error(GraphErrorCode::param_not_structural, where_of(r) + "/size",
            who + ": '$" + name + "' must be structural (a size change recompiles the graph)");
    return 1;
  }
  if (!d->has_range() || d->min < 1 || d->max > kMaxSizeDivisor) {
    s.error(GraphErrorCode::param_range_mismatch, where_of(r) + "/size",
            who + ": '$" + name + "' must have a range inside [1, " +
                std::to_string(kMaxSizeDivisor) + "] to divide a size");
    return 1;
  }
  return s.params.get_int(name);
}

}  // namespace

void index_resources(CompileState& s) {
  const auto& res = s.graph.resources;
  s.resource_index.reserve(res.size());
  s.width.assign(res.size(), 0);
  s.height.assign(res.size(), 0);
  s.version_of.assign(res.size(), {});
  for (size_t i = 0; i < res.size(); ++i) {
    auto [it, inserted] = s.resource_index.emplace(res[i].name, static_cast<int>(i));
    if (!inserted)
      s.error(GraphErrorCode::duplicate_name, where_of(res[i]),
              "resource '" + res[i].name + "' is declared twice");
    if (res[i].kind == ResourceKind::texture || res[i].kind == ResourceKind::persistent)
      res[i].size.resolve(s.settings, divisor_of(s, res[i]), s.width[i], s.height[i]);
  }
}

}  // namespace penumbra::graph::detail
