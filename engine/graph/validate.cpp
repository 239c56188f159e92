// Stage: validate declarations. Never stops at the first error: a technique author fixing a
// graph wants the whole list. Every binding is checked, chosen or not (a typo in a branch the
// defaults do not take is still a typo); what depends on the choice (required slots, sizes)
// is checked on the bindings bind_passes chose.
#include <algorithm>
#include <sstream>

#include "graph/compile_state.h"

namespace penumbra::graph::detail {

namespace {

std::string loc(const std::string& location, const std::string& fallback) {
  return location.empty() ? fallback : location;
}

std::string describe(const PassDecl& p, const std::string& slot, const std::string& resource) {
  std::string s = "pass '" + p.name + "' (" + p.type + ")";
  if (!slot.empty()) s += ", slot '" + slot + "'";
  if (!resource.empty()) s += ", resource '" + resource + "'";
  return s;
}

bool slot_accepts_kind(SlotKind slot, ResourceKind kind) {
  switch (slot) {
    case SlotKind::texture: return kind == ResourceKind::texture || kind == ResourceKind::persistent;
    case SlotKind::buffer: return kind == ResourceKind::buffer;
    case SlotKind::imported: return kind == ResourceKind::imported;
  }
  return false;
}

bool value_has_type(ParamType type, const ParamValue& v) {
  switch (type) {
    case ParamType::boolean: return std::holds_alternative<bool>(v);
    case ParamType::integer: return std::holds_alternative<int>(v);
    case ParamType::real: return std::holds_alternative<int>(v) || std::holds_alternative<double>(v);
    case ParamType::enumeration: return std::holds_alternative<std::string>(v);
  }
  return false;
}

// Up to `count` candidates nearest to `name` by edit distance (a typo's likely intent).
std::vector<std::string> closest_names(const std::string& name, const std::vector<std::string>& candidates, size_t count) {
  auto distance = [](const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
      size_t diagonal = row[0];
      row[0] = i;
      for (size_t j = 1; j <= b.size(); ++j) {
        size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
        diagonal = up;
      }
    }
    return row[b.size()];
  };
  const std::string probe = name.substr(0, 64);
  std::vector<std::pair<size_t, std::string>> ranked;
  for (const std::string& c : candidates) ranked.emplace_back(distance(probe, c), c);
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (size_t i = 0; i < ranked.size() && i < count && ranked[i].first <= std::max<size_t>(3, probe.size() / 2); ++i)
    out.push_back(ranked[i].second);
  return out;
}

std::string range_text(double min, double max) {
  std::ostringstream s;
  s << "[" << min << ", " << max << "]";
  return s.str();
}

// Why a graph parameter bound to a pass parameter could carry a value the pass does not
// accept (the pass type's range, options, unit), or "" when every value it allows fits.
std::string disagreement(const ParamDesc& pass, const ParamDesc& graph) {
  if (pass.type == ParamType::enumeration) {
    for (const std::string& o : graph.options)
      if (std::find(pass.options.begin(), pass.options.end(), o) == pass.options.end())
        return "option \"" + o + "\" is not one the pass type accepts";
  } else if (pass.type != ParamType::boolean && pass.has_range()) {
    if (!graph.has_range())
      return "it has no range; the pass type accepts " + range_text(pass.min, pass.max);
    if (graph.min < pass.min || graph.max > pass.max)
      return "it allows " + range_text(graph.min, graph.max) + ", the pass type accepts " +
             range_text(pass.min, pass.max);
  }
  if (pass.has_step()) {
    // Every value the graph allows must be one of the pass type's steps.
    const bool same_grid = graph.has_step() && graph.step % pass.step == 0 &&
                           nearest_step_value(pass, static_cast<int>(graph.min)) == static_cast<int>(graph.min);
    if (!same_grid)
      return "it allows values off the pass type's steps of " + std::to_string(pass.step) + " from " +
             std::to_string(static_cast<long long>(pass.min)) + " (declare \"step\" in the parameter)";
  }
  if (!pass.unit.empty() && !graph.unit.empty() && pass.unit != graph.unit)
    return "its unit is '" + graph.unit + "', the pass type's is '" + pass.unit + "'";
  return "";
}

// Where a pass is declared, for messages (built only when an error is reported).
std::string pass_location(const PassDecl& p) { return loc(p.location, "pass '" + p.name + "'"); }

// Where a pass's parameters are declared: "/passes/N/params" in a file.
std::string params_location(const PassDecl& p) { return p.location.empty() ? pass_location(p) : p.location + "/params"; }

void validate_slot_binding(CompileState& s, const PassDecl& p, const PassTypeDecl& type, const BoundSlot& bs) {
  const SlotBinding& b = *bs.binding;
  auto where = [&] { return loc(b.location, pass_location(p)); };
  const SlotDecl* slot = bs.slot;
  if (!slot) {
    std::string valid;
    for (const auto& sd : type.slots) valid += (valid.empty() ? "" : ", ") + sd.name;
    s.error(GraphErrorCode::unknown_slot, where(),
            describe(p, b.slot, b.resource) + ": pass type '" + p.type + "' has no slot '" +
                b.slot + "'; slots: " + valid);
    return;
  }
  if (b.resource.empty()) return;  // deliberately unbound (null, or a choice without it)
  if (bs.resource < 0) {
    s.error(GraphErrorCode::unknown_resource, where(),
            describe(p, b.slot, b.resource) + ": no resource named '" + b.resource + "' is declared");
    return;
  }
  if (b.version > kMaxVersion || b.version < -1) {
    s.error(GraphErrorCode::version_out_of_range, where(),
            describe(p, b.slot, b.resource) + ": version " + std::to_string(b.version) +
                " out of range 0.." + std::to_string(kMaxVersion));
  }
  const ResourceDecl& res = s.graph.resources[bs.resource];
  if (!slot_accepts_kind(slot->kind, res.kind)) {
    s.error(GraphErrorCode::format_not_accepted, where(),
            describe(p, b.slot, b.resource) + ": slot takes a " + slot_kind_name(slot->kind) +
                ", resource is " + resource_kind_name(res.kind));
    return;
  }
  if (slot->tile_list && !res.tile_list) {
    s.error(GraphErrorCode::format_not_accepted, where(),
            describe(p, b.slot, b.resource) + ": slot takes a tile list, a buffer declared with \"tiles\" (e.g. "
            "\"tiles\": \"screen/8\"); '" + res.name + "' is a buffer of " + std::to_string(res.bytes) + " bytes");
    return;
  }
  bool textured = res.kind == ResourceKind::texture || res.kind == ResourceKind::persistent;
  if (textured && !slot->formats.empty() &&
      std::find(slot->formats.begin(), slot->formats.end(), res.format) == slot->formats.end()) {
    std::string accepted;
    for (Format f : slot->formats) accepted += (accepted.empty() ? "" : ", ") + std::string(format_name(f));
    s.error(GraphErrorCode::format_not_accepted, where(),
            describe(p, b.slot, b.resource) + ": format " + format_name(res.format) +
                " not accepted; slot accepts " + accepted);
  }
}

// Every declared binding, then what bind_passes chose: required slots and same-size groups.
void validate_slots(CompileState& s, const BoundPass& bp) {
  const PassDecl& p = *bp.decl;
  const PassTypeDecl& type = *bp.type;
  for (size_t i = 0; i < bp.declared.size(); ++i) {
    const SlotBinding& b = *bp.declared[i].binding;
    validate_slot_binding(s, p, type, bp.declared[i]);
    // A binding after an unconditional one of the same slot can never apply.
    for (size_t j = 0; j < i; ++j)
      if (p.slots[j].slot == b.slot && p.slots[j].when.empty()) {
        s.error(GraphErrorCode::duplicate_name, loc(b.location, pass_location(p)),
                describe(p, b.slot, b.resource) + ": slot is already bound (unconditionally)");
        break;
      }
  }
  for (const SlotDecl& sd : type.slots) {
    if (!sd.required) continue;
    bool bound = std::any_of(bp.slots.begin(), bp.slots.end(), [&](const BoundSlot& b) { return b.slot == &sd; });
    if (!bound)
      s.error(GraphErrorCode::missing_required_slot, pass_location(p),
              describe(p, sd.name, "") + ": required slot is not bound" +
                  (p.slots.empty() ? "" : " for these parameter values"));
  }
  for (const auto& group : type.same_size_groups) {
    const BoundSlot* first = nullptr;
    for (const BoundSlot& b : bp.slots) {
      if (b.resource < 0 || s.width[b.resource] == 0 || !b.slot ||
          std::find(group.begin(), group.end(), b.slot->name) == group.end())
        continue;
      if (!first) {
        first = &b;
        continue;
      }
      const int fw = s.width[first->resource], fh = s.height[first->resource];
      const int w = s.width[b.resource], h = s.height[b.resource];
      if (w != fw || h != fh)
        s.error(GraphErrorCode::size_mismatch, loc(b.binding->location, pass_location(p)),
                describe(p, b.binding->slot, b.binding->resource) + ": size " + std::to_string(w) + "x" +
                    std::to_string(h) + " differs from slot '" + first->binding->slot + "' (resource '" +
                    first->binding->resource + "', " + std::to_string(fw) + "x" + std::to_string(fh) +
                    "); these slots must have the same size");
    }
  }
}

// A `$`-bound or exposed pass parameter must be able to take every value its graph parameter
// allows.
void validate_reference(CompileState& s, const PassDecl& p, const ParamDesc& desc,
                        const ParamDesc& graph_param, const std::string& where) {
  const std::string who = "pass '" + p.name + "', parameter '" + desc.name + "'";
  const std::string ref = "'$" + graph_param.name + "' (" + param_location(s, graph_param.name) + ")";
  if (!value_has_type(desc.type, graph_param.default_value)) {
    s.error(GraphErrorCode::param_wrong_type, where,
            who + ": expects " + param_type_name(desc.type) + ", " + ref + " is " +
                param_type_name(graph_param.type));
    return;
  }
  if (std::string why = disagreement(desc, graph_param); !why.empty())
    s.error(GraphErrorCode::param_range_mismatch, where, who + " takes " + ref + ", but " + why);
}

// The graph parameter exposing this pass parameter, if any.
const ParamExposure* exposure_of(const CompileState& s, const PassDecl& p, const std::string& param) {
  for (const ParamExposure& e : s.graph.exposures)
    if (e.pass == p.name && e.pass_param == param) return &e;
  return nullptr;
}

// An exposed pass parameter may also be bound explicitly only to the graph parameter exposing
// it (a template binding every pass alike, say): any other binding would give it two values.
void validate_exposure_bindings(CompileState& s, const PassDecl& p, const ParamDesc& desc) {
  const ParamExposure* exposure = exposure_of(s, p, desc.name);
  if (!exposure) return;
  for (const ParamBinding& b : p.params)
    if (b.name == desc.name && b.reference != exposure->parameter)
      s.error(GraphErrorCode::param_bound_twice, loc(b.location, pass_location(p)),
              "pass '" + p.name + "', parameter '" + desc.name + "': bound here and exposed by parameter '" +
                  exposure->parameter + "' (" + loc(exposure->location, param_location(s, exposure->parameter)) +
                  "); keep one");
}

// A pass parameter no binding applies to: it takes its exposure's graph parameter, or the pass
// type's default, which a required parameter lacks. One that shares a graph parameter's name
// was most likely meant to take it: nothing binds by name, so that is an error too.
void validate_unbound(CompileState& s, const PassDecl& p, const BoundParam& bound) {
  const ParamDesc& desc = *bound.desc;
  const std::string who = "pass '" + p.name + "', parameter '" + desc.name + "'";
  if (bound.exposure) {
    if (bound.graph_param)
      validate_reference(s, p, desc, *bound.graph_param, loc(bound.exposure->location, pass_location(p)));
    return;
  }
  const bool left_unbound = std::any_of(p.params.begin(), p.params.end(), [&](const ParamBinding& b) {
    return b.name == desc.name && b.unbound && s.holds(b.when);
  });
  if (desc.required) {
    s.error(GraphErrorCode::param_unbound, params_location(p),
            who + ": the pass type declares no default; bind it (a constant or \"$param\")" +
                (left_unbound ? " for these parameter values" : ""));
  } else if (!left_unbound && !p.frame && s.params.find(desc.name)) {
    s.error(GraphErrorCode::param_unbound, params_location(p),
            who + " is unbound and takes the pass type's default " + param_value_to_string(desc.default_value) +
                ", though graph parameter '" + desc.name + "' (" + param_location(s, desc.name) +
                ") has its name; nothing binds by name: bind \"$" + desc.name + "\", expose it (\"exposes\": \"" +
                p.name + "." + desc.name + "\") or bind a constant");
  }
}

void validate_params(CompileState& s, const BoundPass& bp) {
  const PassDecl& p = *bp.decl;
  const PassTypeDecl& type = *bp.type;
  for (size_t i = 0; i < p.params.size(); ++i) {
    const ParamBinding& b = p.params[i];
    auto where = [&] { return loc(b.location, pass_location(p)); };
    auto who = [&] { return "pass '" + p.name + "', parameter '" + b.name + "'"; };
    const ParamDesc* desc = type.find_param(b.name);
    if (!desc) {
      std::string valid;
      for (const auto& d : type.params) valid += (valid.empty() ? "" : ", ") + d.name;
      s.error(GraphErrorCode::param_unknown, where(),
              who() + ": pass type '" + p.type + "' has no such parameter; parameters: " +
                  (valid.empty() ? "(none)" : valid));
      continue;
    }
    for (size_t j = 0; j < i; ++j)
      if (p.params[j].name == b.name && p.params[j].when.empty()) {
        s.error(GraphErrorCode::duplicate_name, where(), who() + ": already bound (unconditionally)");
        break;
      }
    if (b.unbound) continue;
    if (!b.reference.empty()) {
      if (const ParamDesc* graph_param = s.params.find(b.reference))
        validate_reference(s, p, *desc, *graph_param, where());
      else
        s.error(GraphErrorCode::unknown_param_reference, where(),
                who() + ": '$" + b.reference + "' is not a parameter of graph '" + s.graph.name + "'");
      continue;
    }
    if (!value_has_type(desc->type, b.constant)) {
      s.error(GraphErrorCode::param_wrong_type, where(),
              who() + ": expects " + param_type_name(desc->type) + ", got " + param_value_to_string(b.constant));
    } else if (Status st = check_param_value(*desc, b.constant); !st) {
      s.error(GraphErrorCode::param_out_of_range, where(), who() + ": " + st.error().message);
    }
  }
  for (const BoundParam& bound : bp.params) {
    validate_exposure_bindings(s, p, *bound.desc);
    if (!bound.binding) validate_unbound(s, p, bound);
  }
}

void validate_repeat(CompileState& s, const PassDecl& p) {
  if (p.repeat_reference.empty() && p.repeat >= 1 && p.repeat <= kMaxRepeat) return;
  const std::string where = pass_location(p) + "/repeat";
  const std::string limit = "[1, " + std::to_string(kMaxRepeat) + "]";
  if (p.repeat_reference.empty()) {
    s.error(GraphErrorCode::repeat_out_of_range, where,
            "pass '" + p.name + "': repeat " + std::to_string(p.repeat) + " is out of range " + limit);
    return;
  }
  const std::string who = "pass '" + p.name + "': repeat '$" + p.repeat_reference + "'";
  const ParamDesc* d = s.params.find(p.repeat_reference);
  if (!d) {
    s.error(GraphErrorCode::unknown_param_reference, where,
            who + " is not a parameter of graph '" + s.graph.name + "'");
  } else if (d->type != ParamType::integer) {
    s.error(GraphErrorCode::param_wrong_type, where, who + " must be int, is " + param_type_name(d->type));
  } else if (!d->structural) {
    s.error(GraphErrorCode::param_not_structural, where,
            who + " is not structural: the plan would not be rebuilt when it changes");
  } else if (!d->has_range() || d->min < 1 || d->max > kMaxRepeat) {
    s.error(GraphErrorCode::repeat_out_of_range, where,
            who + " must have a range inside " + limit + ", has " +
                (d->has_range() ? range_text(d->min, d->max) : std::string("none")));
  }
}

}  // namespace

// Where the graph declares parameter `name`: "/parameters/N" in a file, its name otherwise.
std::string param_location(const CompileState& s, const std::string& name) {
  const auto& ps = s.graph.parameters;
  for (size_t i = 0; i < ps.size(); ++i)
    if (ps[i].name == name)
      return s.graph.source_file.empty() ? "parameter '" + name + "'" : "/parameters/" + std::to_string(i);
  return "parameter '" + name + "'";
}

void validate_declarations(CompileState& s) {
  std::unordered_map<std::string_view, int> pass_names;
  pass_names.reserve(s.bound.size());
  for (const BoundPass& bp : s.bound) {
    const PassDecl& p = *bp.decl;
    if (!pass_names.emplace(p.name, 0).second)
      s.error(GraphErrorCode::duplicate_name, pass_location(p), "pass '" + p.name + "' is declared twice");
    if (!bp.type) {
      const std::vector<std::string> known = s.registry.names();
      std::string near;
      for (const std::string& n : closest_names(p.type, known, 3)) near += (near.empty() ? "" : ", ") + n;
      s.error(GraphErrorCode::unknown_pass_type, pass_location(p),
              "pass '" + p.name + "': unknown pass type '" + shortened(p.type) + "'" +
                  (near.empty() ? "" : "; closest: " + near) + " (" + std::to_string(known.size()) +
                  " types are registered; `penumbra graph --pass-types` lists them)");
    } else {
      validate_slots(s, bp);
      validate_params(s, bp);
    }
    validate_repeat(s, p);
  }
  for (size_t i = 0; i < s.graph.outputs.size(); ++i)
    if (s.find_resource(s.graph.outputs[i]) < 0)
      s.error(GraphErrorCode::unknown_output, "/outputs/" + std::to_string(i),
              "output '" + s.graph.outputs[i] + "' is not a declared resource");
  validate_parameter_graph(s);
}

}  // namespace penumbra::graph::detail
