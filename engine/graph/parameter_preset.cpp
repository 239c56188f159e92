#include "graph/parameter_preset.h"

#include <nlohmann/json.hpp>

#include "util/json_text.h"

namespace penumbra::graph {

std::string format_preset(const std::string& technique, const ParameterSet& params) {
  nlohmann::ordered_json j;
  j["technique"] = technique;
  j["parameters"] = nlohmann::ordered_json::parse(params.to_json());
  return j.dump(2) + "\n";
}

Result<Preset> parse_preset(const std::string& text, const std::string& source) {
  auto fail = [&](std::string message, std::string where = "") {
    Error e = make_error(std::move(message));
    e.file = source;
    e.where = std::move(where);
    return e;
  };
  // Nesting (nlohmann recurses), overflowing numbers and keys given twice: before parsing.
  if (std::optional<JsonTextProblem> p = scan_json_text(text)) {
    Error e = fail("preset: " + p->message);
    e.line = p->line;
    e.column = p->column;
    return e;
  }
  nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return fail("preset is not valid JSON");
  if (!j.is_object()) return fail("a preset must be an object {\"technique\": ..., \"parameters\": {...}}");
  for (const auto& [key, value] : j.items())
    if (key != "technique" && key != "parameters")
      return fail("unknown key '" + key + "' (expected \"technique\" and \"parameters\")", "/" + key);
  if (!j.contains("technique") || !j["technique"].is_string())
    return fail("missing string \"technique\"", "/technique");
  if (!j.contains("parameters") || !j["parameters"].is_object())
    return fail("missing object \"parameters\"", "/parameters");
  return Preset{j["technique"].get<std::string>(), j["parameters"].dump()};
}

Result<ParameterSet> preset_applied(const Preset& preset, const std::string& technique,
                                           const ParameterSet& current) {
  if (preset.technique != technique)
    return make_error("preset is for technique '" + preset.technique + "', the active technique is '" +
                      technique + "': nothing applied");
  ParameterSet next = current;
  if (Status s = next.apply_json(preset.parameters_json); !s) {
    Error e = s.error();
    e.message = "preset not applied: " + e.message;
    return e;
  }
  return next;
}

}  // namespace penumbra::graph
