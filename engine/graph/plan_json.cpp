// The plan as JSON (`penumbra graph FILE --json OUT.json`), for scripts: the same facts as the
// text dump, plus each pass's traffic.
#include <nlohmann/json.hpp>

#include "graph/plan.h"

namespace penumbra::graph {

namespace {
using Json = nlohmann::ordered_json;

Json binding_json(const PlannedBinding& b) {
  Json j = {{"slot", b.slot}, {"access", access_name(b.access)}, {"usage", usage_name(b.usage)},
            {"resource", b.resource}};
  if (b.read_version >= 0) j["read_version"] = b.read_version;
  if (b.write_version >= 0) j["write_version"] = b.write_version;
  j["physical"] = b.physical >= 0 ? Json(b.physical) : Json(nullptr);
  return j;
}

Json pass_json(const PlannedPass& p) {
  Json bindings = Json::array();
  for (const PlannedBinding& b : p.bindings) bindings.push_back(binding_json(b));
  Json params = Json::object();
  for (const PlannedParam& pp : p.params) {
    Json value;
    std::visit([&](const auto& v) { value = v; }, pp.value);
    params[pp.name] = pp.reference.empty() ? value : Json{{"reference", pp.reference}, {"value", value}};
  }
  return {{"name", p.name},
          {"type", p.type},
          {"declared_as", p.declared_as},
          {"iteration", p.iteration},
          {"frame", p.frame},
          {"barriers", barrier_bits_to_string(p.barriers)},
          {"bindings", bindings},
          {"params", params},
          {"traffic", {{"read_bytes", p.traffic.read_bytes}, {"written_bytes", p.traffic.written_bytes}}}};
}

Json physical_json(const PhysicalResource& r) {
  Json j = {{"id", r.id}, {"kind", resource_kind_name(r.kind)}};
  if (r.kind != ResourceKind::buffer) {
    j["format"] = format_name(r.format);
    j["width"] = r.width;
    j["height"] = r.height;
  }
  j["bytes"] = r.bytes;
  j["holds"] = r.holds;
  return j;
}

}  // namespace

std::string to_json(const CompiledPlan& plan) {
  Json passes = Json::array();
  for (const PlannedPass& p : plan.passes) passes.push_back(pass_json(p));
  Json physical = Json::array();
  for (const PhysicalResource& r : plan.physical) physical.push_back(physical_json(r));
  Json j = {{"graph", plan.graph_name},
            {"screen", {plan.settings.screen_w, plan.settings.screen_h}},
            {"shadow_size", plan.settings.shadow_size},
            {"passes", passes},
            {"culled", plan.culled},
            {"disabled", plan.disabled},
            {"physical", physical},
            {"outputs", plan.outputs},
            {"memory", {{"naive_bytes", plan.memory.naive_bytes}, {"assigned_bytes", plan.memory.assigned_bytes}}}};
  return j.dump(2) + "\n";
}

}  // namespace penumbra::graph
