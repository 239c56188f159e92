#include "app/preset.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace penumbra::sandbox {

std::string format_preset(const std::string& technique, const graph::ParameterSet& params) {
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

Result<graph::ParameterSet> preset_applied(const Preset& preset, const std::string& technique,
                                           const graph::ParameterSet& current) {
  if (preset.technique != technique)
    return make_error("preset is for technique '" + preset.technique + "', the active technique is '" +
                      technique + "': nothing applied");
  graph::ParameterSet next = current;
  if (Status s = next.apply_json(preset.parameters_json); !s) {
    Error e = s.error();
    e.message = "preset not applied: " + e.message;
    return e;
  }
  return next;
}

Status write_text_file(const std::string& path, const std::string& text) {
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (out && (out << text) && out.flush()) return {};
  }
  std::remove(path.c_str());  // never leave a partial file
  Error e = make_error("cannot write file");
  e.file = path;
  return e;
}

}  // namespace penumbra::sandbox
