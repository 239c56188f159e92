#pragma once
// Parameters are described ONCE (ParamDesc) and every consumer reads that description: the
// sandbox UI (widgets from type/min/max/unit), JSON presets (apply_json/to_json), the CLI
// (`--set k=v` through set_from_string), pass-type declarations and tests.
//
//   ParameterSet params({
//       {.name = "blur_radius", .type = ParamType::integer, .default_value = 4, .min = 1,
//        .max = 16, .unit = "texels", .description = "Gaussian radius per pass"},
//       {.name = "use_blur", .type = ParamType::boolean, .default_value = true,
//        .description = "Run the blur passes", .structural = true},
//   });
//   if (Status s = params.set_from_string("blur_radius=6"); !s) print(s.error());
//   int r = params.get_int("blur_radius");
//
// Structural parameters change the graph's shape (enabled / repeat); changing one means
// compiling again. Non-structural ones are uniforms: the compiled plan keeps "$name"
// references to them so the executor reads the current value every frame.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <string_view>
#include <variant>
#include <vector>

#include "util/error.h"

namespace penumbra::graph {

enum class ParamType { boolean, integer, real, enumeration };

// bool for boolean, int for integer, double for real, std::string for enumeration.
using ParamValue = std::variant<bool, int, double, std::string>;

struct ParamDesc {
  std::string name;
  ParamType type = ParamType::real;
  ParamValue default_value = 0.0;
  double min = 0.0;  // inclusive; ignored for boolean and enumeration
  double max = 0.0;  // inclusive; min == max == 0 means "unbounded"
  std::string unit;  // "texels", "shadow-map UV", "world units", ... (empty: unitless)
  std::string description;  // one line, shown as the UI tooltip and in `--help`
  bool structural = false;  // true: changing it recompiles the graph
  std::vector<std::string> options;  // enumeration values
  // Integers only: valid values are min + k * step (step 2 from an odd min = odd sizes of a
  // kernel centred on a pixel). 0 = every integer. Checked like the range, so a UI offers only
  // valid values and a bad one is refused when set rather than by a pass every frame.
  int step = 0;
  // A condition (condition.h syntax) on the graph's parameters, structural or not, under which
  // this parameter has an effect ("$kernel == \"vogel\""); empty = always. For switches inside
  // one pass, which the graph's `enabled` conditions cannot show; the sandbox greys the widget out.
  std::string applies;
  // Another parameter that caps this one's effect while `when` holds (condition.h syntax; empty =
  // always), e.g. a search radius whose filter never exceeds a maximum size. The sandbox marks
  // the widget "capped by <param>" with `why`, so a slider that seems to do nothing says why.
  struct Cap {
    std::string param, when, why;
  };
  std::optional<Cap> capped_by;
  // Pass types only: the parameter has no default, so every pass of the type must bind it (a
  // separable filter's axis, say, where a default would hide a forgotten binding).
  bool required = false;

  // The conditions a UI evaluates ("applies", "capped_by/when"), with the JSON key each sits under.
  std::vector<std::pair<std::string, std::string>> ui_conditions() const {
    std::vector<std::pair<std::string, std::string>> out;
    if (!applies.empty()) out.emplace_back("applies", applies);
    if (capped_by && !capped_by->when.empty()) out.emplace_back("capped_by/when", capped_by->when);
    return out;
  }

  bool has_range() const { return min != 0.0 || max != 0.0; }
  bool has_step() const { return type == ParamType::integer && step > 1; }
};

const char* param_type_name(ParamType type);
// "true", "3", "0.25", "\"mask\"" (strings quoted) — for messages and text dumps.
std::string param_value_to_string(const ParamValue& value);
// Does `value` fit `desc` (type, range, enum option)? The error says what was expected.
Status check_param_value(const ParamDesc& desc, const ParamValue& value);
// The valid value nearest `value` for an integer parameter with a step (ties go up); `value`
// itself otherwise. The range is not applied.
int nearest_step_value(const ParamDesc& desc, int value);
// Parses text as a value of desc.type ("true"/"false"/"1"/"0", integer, real, option name).
Result<ParamValue> parse_param_value(const ParamDesc& desc, std::string_view text);

// Short constructors for declarations in C++ (pass types; techniques describe theirs in JSON).
ParamDesc real_param(std::string name, double def, double min, double max, std::string unit,
                     std::string description);
ParamDesc int_param(std::string name, int def, int min, int max, std::string unit, std::string description);
ParamDesc bool_param(std::string name, bool def, std::string description);
ParamDesc enum_param(std::string name, std::string def, std::vector<std::string> options,
                     std::string description);

class ParameterSet {
 public:
  ParameterSet() = default;
  explicit ParameterSet(std::vector<ParamDesc> descs);  // values start at their defaults

  const std::vector<ParamDesc>& descs() const { return descs_; }
  const ParamDesc* find(std::string_view name) const;
  const ParamValue* get(std::string_view name) const;
  bool get_bool(std::string_view name) const;
  int get_int(std::string_view name) const;
  double get_real(std::string_view name) const;  // integer params are converted
  std::string get_enum(std::string_view name) const;

  // Type- and range-checked; on error nothing changes.
  Status set(std::string_view name, ParamValue value);
  // "k=v" as given on the command line (`--set blur_radius=6`).
  Status set_from_string(std::string_view assignment);
  // A JSON object {"k": v, ...}; all-or-nothing: on any error no value is changed and the
  // error lists every bad key.
  Status apply_json(std::string_view json_text);
  // {"k": v, ...} for every parameter, in declaration order.
  std::string to_json() const;

  void reset(std::string_view name);
  void reset_all();

 private:
  Error unknown_key_error(std::string_view name) const;
  std::vector<ParamDesc> descs_;
  std::vector<ParamValue> values_;
};

// A list of "k=v" assignments (`--set`, a --techniques item's settings) with no key twice: the
// later value would silently win. The error names `option`, the key and both assignments.
Status check_assignment_keys(const std::string& option, const std::vector<std::string>& assignments);

}  // namespace penumbra::graph
