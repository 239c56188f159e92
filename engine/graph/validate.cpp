// Stages 1-2: index resources and validate declarations. Validation never stops at the first
// error: a technique author fixing a graph wants the whole list.
#include <algorithm>

#include "graph/compile_state.h"
#include "graph/condition.h"

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

void validate_slots(CompileState& s, const PassDecl& p, const PassTypeDecl& type) {
  const std::string pass_loc = loc(p.location, "pass '" + p.name + "'");
  for (const SlotBinding& b : p.slots) {
    const std::string where = loc(b.location, pass_loc);
    const SlotDecl* slot = type.find_slot(b.slot);
    if (!slot) {
      std::string valid;
      for (const auto& sd : type.slots) valid += (valid.empty() ? "" : ", ") + sd.name;
      s.error(GraphErrorCode::unknown_slot, where,
              describe(p, b.slot, b.resource) + ": pass type '" + p.type +
                  "' has no slot '" + b.slot + "'; slots: " + valid);
      continue;
    }
    int r = s.find_resource(b.resource);
    if (r < 0) {
      s.error(GraphErrorCode::unknown_resource, where,
              describe(p, b.slot, b.resource) + ": no resource named '" + b.resource +
                  "' is declared");
      continue;
    }
    if (b.version > kMaxVersion || b.version < -1) {
      s.error(GraphErrorCode::unknown_resource, where,
              describe(p, b.slot, b.resource) + ": version " + std::to_string(b.version) +
                  " out of range 0.." + std::to_string(kMaxVersion));
    }
    const ResourceDecl& res = s.graph.resources[r];
    if (!slot_accepts_kind(slot->kind, res.kind)) {
      s.error(GraphErrorCode::format_not_accepted, where,
              describe(p, b.slot, b.resource) + ": slot takes a " +
                  slot_kind_name(slot->kind) + ", resource is " +
                  resource_kind_name(res.kind));
      continue;
    }
    bool textured = res.kind == ResourceKind::texture || res.kind == ResourceKind::persistent;
    if (textured && !slot->formats.empty() &&
        std::find(slot->formats.begin(), slot->formats.end(), res.format) == slot->formats.end()) {
      std::string accepted;
      for (Format f : slot->formats) accepted += (accepted.empty() ? "" : ", ") + std::string(format_name(f));
      s.error(GraphErrorCode::format_not_accepted, where,
              describe(p, b.slot, b.resource) + ": format " + format_name(res.format) +
                  " not accepted; slot accepts " + accepted);
    }
  }
  for (const SlotDecl& sd : type.slots) {
    if (!sd.required) continue;
    bool bound = std::any_of(p.slots.begin(), p.slots.end(),
                             [&](const SlotBinding& b) { return b.slot == sd.name; });
    if (!bound)
      s.error(GraphErrorCode::missing_required_slot, pass_loc,
              describe(p, sd.name, "") + ": required slot is not bound");
  }
  // Same-size groups: every bound texture of a group resolves to one size.
  for (const auto& group : type.same_size_groups) {
    const SlotBinding* first = nullptr;
    int fw = 0, fh = 0;
    for (const std::string& slot_name : group) {
      for (const SlotBinding& b : p.slots) {
        if (b.slot != slot_name) continue;
        int r = s.find_resource(b.resource);
        if (r < 0 || s.width[r] == 0) continue;
        if (!first) {
          first = &b;
          fw = s.width[r];
          fh = s.height[r];
        } else if (s.width[r] != fw || s.height[r] != fh) {
          s.error(GraphErrorCode::size_mismatch, loc(b.location, pass_loc),
                  describe(p, b.slot, b.resource) + ": size " + std::to_string(s.width[r]) +
                      "x" + std::to_string(s.height[r]) + " differs from slot '" +
                      first->slot + "' (resource '" + first->resource + "', " +
                      std::to_string(fw) + "x" + std::to_string(fh) +
                      "); these slots must have the same size");
        }
      }
    }
  }
}

void validate_params(CompileState& s, const PassDecl& p, const PassTypeDecl& type) {
  const std::string pass_loc = loc(p.location, "pass '" + p.name + "'");
  for (const ParamBinding& b : p.params) {
    const std::string where = loc(b.location, pass_loc);
    const std::string who = "pass '" + p.name + "', parameter '" + b.name + "'";
    const ParamDesc* desc = type.find_param(b.name);
    if (!desc) {
      std::string valid;
      for (const auto& d : type.params) valid += (valid.empty() ? "" : ", ") + d.name;
      s.error(GraphErrorCode::param_unknown, where,
              who + ": pass type '" + p.type + "' has no such parameter; parameters: " +
                  (valid.empty() ? "(none)" : valid));
      continue;
    }
    if (!b.reference.empty()) {
      const ParamDesc* tech = s.params.find(b.reference);
      if (!tech) {
        s.error(GraphErrorCode::unknown_param_reference, where,
                who + ": '$" + b.reference + "' is not a parameter of graph '" +
                    s.graph.name + "'");
      } else if (!value_has_type(desc->type, tech->default_value)) {
        s.error(GraphErrorCode::param_wrong_type, where,
                who + ": expects " + param_type_name(desc->type) + ", '$" + b.reference +
                    "' is " + param_type_name(tech->type));
      }
      continue;
    }
    if (!value_has_type(desc->type, b.constant)) {
      s.error(GraphErrorCode::param_wrong_type, where,
              who + ": expects " + param_type_name(desc->type) + ", got " +
                  param_value_to_string(b.constant));
    } else if (Status st = check_param_value(*desc, b.constant); !st) {
      s.error(GraphErrorCode::param_out_of_range, where, who + ": " + st.error().message);
    }
  }
}

void validate_repeat_and_enabled(CompileState& s, const PassDecl& p) {
  const std::string pass_loc = loc(p.location, "pass '" + p.name + "'");
  if (!p.repeat_reference.empty()) {
    const ParamDesc* d = s.params.find(p.repeat_reference);
    if (!d) {
      s.error(GraphErrorCode::unknown_param_reference, pass_loc + "/repeat",
              "pass '" + p.name + "': repeat '$" + p.repeat_reference +
                  "' is not a parameter of graph '" + s.graph.name + "'");
    } else if (d->type != ParamType::integer) {
      s.error(GraphErrorCode::param_wrong_type, pass_loc + "/repeat",
              "pass '" + p.name + "': repeat '$" + p.repeat_reference + "' must be int, is " +
                  param_type_name(d->type));
    } else {
      int n = s.params.get_int(p.repeat_reference);
      if (n < 1 || n > kMaxRepeat)
        s.error(GraphErrorCode::repeat_out_of_range, pass_loc + "/repeat",
                "pass '" + p.name + "': repeat '$" + p.repeat_reference + "' = " +
                    std::to_string(n) + " is out of range [1, " + std::to_string(kMaxRepeat) + "]");
    }
  } else if (p.repeat < 1 || p.repeat > kMaxRepeat) {
    s.error(GraphErrorCode::repeat_out_of_range, pass_loc + "/repeat",
            "pass '" + p.name + "': repeat " + std::to_string(p.repeat) +
                " is out of range [1, " + std::to_string(kMaxRepeat) + "]");
  }
  if (!p.enabled.empty()) {
    Result<Condition> c = Condition::parse(p.enabled);
    Status st = c ? c->check(s.params) : Status{c.error()};
    if (!st) {
      bool unknown = st.error().message.find("unknown parameter") != std::string::npos;
      s.error(unknown ? GraphErrorCode::unknown_param_reference : GraphErrorCode::bad_condition,
              pass_loc + "/enabled", "pass '" + p.name + "': " + st.error().message);
    }
  }
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
      s.error(GraphErrorCode::duplicate_name, loc(res[i].location, "resource '" + res[i].name + "'"),
              "resource '" + res[i].name + "' is declared twice");
    if (res[i].kind == ResourceKind::texture || res[i].kind == ResourceKind::persistent)
      res[i].size.resolve(s.settings, s.width[i], s.height[i]);
  }
}

void validate_declarations(CompileState& s) {
  std::unordered_map<std::string_view, int> pass_names;
  for (const PassDecl& p : s.graph.passes) {
    if (!pass_names.emplace(p.name, 0).second)
      s.error(GraphErrorCode::duplicate_name, loc(p.location, "pass '" + p.name + "'"),
              "pass '" + p.name + "' is declared twice");
    const PassTypeDecl* type = s.registry.find(p.type);
    if (!type) {
      std::string known;
      for (const auto& n : s.registry.names()) known += (known.empty() ? "" : ", ") + n;
      s.error(GraphErrorCode::unknown_pass_type, loc(p.location, "pass '" + p.name + "'"),
              "pass '" + p.name + "': unknown pass type '" + p.type + "'; known: " + known);
    } else {
      validate_slots(s, p, *type);
      validate_params(s, p, *type);
    }
    validate_repeat_and_enabled(s, p);
  }
  for (size_t i = 0; i < s.graph.outputs.size(); ++i)
    if (s.find_resource(s.graph.outputs[i]) < 0)
      s.error(GraphErrorCode::unknown_output, "/outputs/" + std::to_string(i),
              "output '" + s.graph.outputs[i] + "' is not a declared resource");
}

}  // namespace penumbra::graph::detail
