// One entry of "passes": the shape its templates give it (graph_json_templates.cpp), its own
// keys, and each slot or parameter value turned into bindings (graph_json_choices.cpp reads
// the choices among them).
#include <cstdint>
#include <string>

#include "graph/condition.h"
#include "graph/graph_json_reader.h"
#include "graph/json_values.h"

namespace penumbra::graph::json_detail {

void GraphReader::read_pass(const Json& j, const std::string& ptr, GraphDesc& g) {
  if (!j.is_object()) {
    error(GraphErrorCode::wrong_json_type, ptr, "a pass must be an object");
    return;
  }
  PassDecl p;
  p.location = ptr;
  check_keys(j, ptr, {"type", "name", "extends", "slots", "params", "enabled", "repeat", "side_effect", "description"});
  PassShape shape = extended_shape(j, ptr);
  p.type = shape.type.value_or("");
  get_string(j, "type", ptr, p.type, p.type.empty());
  get_string(j, "name", ptr, p.name, true);
  collect(j, "slots", ptr, shape.slots);
  collect(j, "params", ptr, shape.params);
  for (const auto& [slot, value] : shape.slots) read_slot(slot, value, p, g);
  for (const auto& [name, value] : shape.params) read_param(name, value, p, g);
  std::string enabled;
  get_enabled(j, ptr, enabled);
  p.enabled = condition_and(shape.enabled, enabled);  // a pass's own condition narrows its templates'
  if (auto it = j.find("repeat"); it != j.end()) {
    if (it->is_string() && it->get<std::string>().size() > 1 && it->get<std::string>()[0] == '$')
      p.repeat_reference = it->get<std::string>().substr(1);
    else if (it->is_number_integer() && it->get<std::int64_t>() >= INT32_MIN && it->get<std::int64_t>() <= INT32_MAX)
      p.repeat = static_cast<int>(it->get<std::int64_t>());
    else if (it->is_number())
      error(GraphErrorCode::repeat_out_of_range, ptr + "/repeat",
            "pass '" + p.name + "': repeat out of range [1, " + std::to_string(kMaxRepeat) + "]");
    else
      error(GraphErrorCode::wrong_json_type, ptr + "/repeat", "\"repeat\" must be an integer or \"$param\"");
  }
  if (auto it = j.find("side_effect"); it != j.end()) {
    if (it->is_boolean()) p.side_effect = it->get<bool>();
    else error(GraphErrorCode::wrong_json_type, ptr + "/side_effect", "\"side_effect\" must be true or false");
  }
  g.passes.push_back(std::move(p));
}

void GraphReader::read_slot(const std::string& slot, const Located& value, PassDecl& p, const GraphDesc& g) {
  read_choice(*value.value, value.pointer, "", g, [&](const Json& j, const std::string& ptr, const std::string& when) {
    SlotBinding b;
    b.slot = slot;
    b.location = ptr;
    b.when = when;
    if (j.is_null()) {
      p.slots.push_back(std::move(b));  // unbound
      return;
    }
    if (!j.is_string()) {
      error(GraphErrorCode::wrong_json_type, ptr, "slot '" + shortened(slot) + "' must name a resource (\"name\" or \"name@version\"), null, or a choice");
      return;
    }
    std::string text = j.get<std::string>();
    size_t at = text.find('@');
    b.resource = text.substr(0, at);
    if (at != std::string::npos) {
      std::string digits = text.substr(at + 1);
      bool ok = !digits.empty() && digits.size() <= 5 && digits.find_first_not_of("0123456789") == std::string::npos;
      if (!ok || std::stoi(digits) > kMaxVersion) {
        error(GraphErrorCode::version_out_of_range, ptr,
              "bad version in \"" + shortened(text) + "\"; expected name@N with N in 0.." + std::to_string(kMaxVersion));
        return;
      }
      b.version = std::stoi(digits);
    }
    if (b.resource.empty()) {
      error(GraphErrorCode::wrong_json_type, ptr, "slot '" + shortened(slot) + "' names no resource");
      return;
    }
    p.slots.push_back(std::move(b));
  });
}

void GraphReader::read_param(const std::string& name, const Located& value, PassDecl& p, const GraphDesc& g) {
  read_choice(*value.value, value.pointer, "", g, [&](const Json& j, const std::string& ptr, const std::string& when) {
    ParamBinding b;
    b.name = name;
    b.location = ptr;
    b.when = when;
    if (j.is_null()) {
      b.unbound = true;
      p.params.push_back(std::move(b));
      return;
    }
    JsonValue v = json_to_param_value(j);
    if (!v.ok) {
      error(v.out_of_range ? GraphErrorCode::param_out_of_range : GraphErrorCode::param_wrong_type,
            ptr, "pass '" + p.name + "', parameter '" + shortened(name) + "': " + v.problem);
      return;
    }
    auto* str = std::get_if<std::string>(&v.value);
    if (str && !str->empty() && (*str)[0] == '$') b.reference = str->substr(1);
    else b.constant = v.value;
    p.params.push_back(std::move(b));
  });
}

}  // namespace penumbra::graph::json_detail
