#pragma once
// Internal to the JSON readers (graph_json_parameters.cpp, graph_json_passes.cpp,
// parameters_json.cpp): JSON value -> ParamValue with range checks (util/json_text.h guards
// the text before nlohmann parses it).
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "graph/parameters.h"

namespace penumbra::graph {

struct JsonValue {
  bool ok = false;
  bool out_of_range = false;
  ParamValue value;
  std::string problem;  // when !ok
};

// bool -> bool, integer -> int (must fit 32 bits), finite real -> double, string -> string.
template <class Json>
JsonValue json_to_param_value(const Json& j) {
  JsonValue v;
  if (j.is_boolean()) {
    v.value = j.template get<bool>();
  } else if (j.is_number_unsigned() || j.is_number_integer()) {
    bool fits = j.is_number_unsigned() ? j.template get<std::uint64_t>() <= INT32_MAX
                                       : (j.template get<std::int64_t>() >= INT32_MIN &&
                                          j.template get<std::int64_t>() <= INT32_MAX);
    if (!fits) {
      v.out_of_range = true;
      v.problem = "integer " + j.dump() + " does not fit in 32 bits";
      return v;
    }
    v.value = static_cast<int>(j.template get<std::int64_t>());
  } else if (j.is_number_float()) {
    double d = j.template get<double>();
    if (!std::isfinite(d)) {
      v.out_of_range = true;
      v.problem = "number " + j.dump() + " is not finite";
      return v;
    }
    v.value = d;
  } else if (j.is_string()) {
    v.value = j.template get<std::string>();
  } else {
    v.problem = std::string("expected a bool, number or string, got ") + j.type_name();
    return v;
  }
  v.ok = true;
  return v;
}

inline std::optional<ParamType> parse_param_type(std::string_view s) {
  if (s == "bool") return ParamType::boolean;
  if (s == "int") return ParamType::integer;
  if (s == "float") return ParamType::real;
  if (s == "enum") return ParamType::enumeration;
  return std::nullopt;
}

}  // namespace penumbra::graph
