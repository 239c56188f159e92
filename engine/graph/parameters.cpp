#include "graph/parameters.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

namespace penumbra::graph {

const char* param_type_name(ParamType type) {
  switch (type) {
    case ParamType::boolean: return "bool";
    case ParamType::integer: return "int";
    case ParamType::real: return "float";
    case ParamType::enumeration: return "enum";
  }
  return "?";
}

std::string param_value_to_string(const ParamValue& value) {
  struct Visitor {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(int i) const { return std::to_string(i); }
    std::string operator()(double d) const {
      std::ostringstream s;
      s << d;
      return s.str();
    }
    std::string operator()(const std::string& str) const { return "\"" + str + "\""; }
  };
  return std::visit(Visitor{}, value);
}

static const char* value_type_name(const ParamValue& v) {
  switch (v.index()) {
    case 0: return "bool";
    case 1: return "int";
    case 2: return "float";
    default: return "string";
  }
}

static std::string range_text(const ParamDesc& d) {
  std::ostringstream s;
  s << "[" << d.min << ", " << d.max << "]";
  if (!d.unit.empty()) s << " " << d.unit;
  return s.str();
}

Status check_param_value(const ParamDesc& desc, const ParamValue& value) {
  auto wrong_type = [&] {
    Error e = make_error("parameter '" + desc.name + "' expects " +
                         param_type_name(desc.type) + ", got " + value_type_name(value) + " " +
                         param_value_to_string(value));
    e.where = desc.name;
    return e;
  };
  double numeric = 0.0;
  switch (desc.type) {
    case ParamType::boolean:
      if (!std::holds_alternative<bool>(value)) return wrong_type();
      return {};
    case ParamType::integer:
      if (!std::holds_alternative<int>(value)) return wrong_type();
      numeric = std::get<int>(value);
      break;
    case ParamType::real:
      // An integer literal is a fine real ("radius": 2 for a float parameter).
      if (std::holds_alternative<int>(value)) numeric = std::get<int>(value);
      else if (std::holds_alternative<double>(value)) numeric = std::get<double>(value);
      else return wrong_type();
      if (!std::isfinite(numeric)) return wrong_type();
      break;
    case ParamType::enumeration: {
      if (!std::holds_alternative<std::string>(value)) return wrong_type();
      const auto& s = std::get<std::string>(value);
      for (const auto& o : desc.options)
        if (o == s) return {};
      std::string list;
      for (const auto& o : desc.options) list += (list.empty() ? "" : ", ") + o;
      Error e = make_error("parameter '" + desc.name + "' has no option \"" + s +
                           "\"; options: " + list);
      e.where = desc.name;
      return e;
    }
  }
  if (desc.has_range() && (numeric < desc.min || numeric > desc.max)) {
    Error e = make_error("parameter '" + desc.name + "' = " + param_value_to_string(value) +
                         " is out of range " + range_text(desc));
    e.where = desc.name;
    return e;
  }
  if (desc.has_step() && nearest_step_value(desc, std::get<int>(value)) != std::get<int>(value)) {
    const long long base = static_cast<long long>(desc.min);
    std::ostringstream valid;
    if (desc.step == 2) valid << "must be " << (base % 2 != 0 ? "odd" : "even") << "; valid: ";
    else valid << "must be " << base << " + k * " << desc.step << "; valid: ";
    // Every valid value when there are few (8, 16), else the first three and the last.
    const long long last = desc.has_range() ? nearest_step_value(desc, static_cast<int>(desc.max) - desc.step / 2) : -1;
    if (desc.has_range() && (last - base) / desc.step < 4) {
      for (long long v = base; v <= last; v += desc.step) valid << (v == base ? "" : ", ") << v;
    } else {
      valid << base << ", " << base + desc.step << ", " << base + 2 * desc.step << ", ...";
      if (desc.has_range()) valid << ", " << last;
    }
    Error e = make_error("parameter '" + desc.name + "' = " + param_value_to_string(value) + " " + valid.str());
    e.where = desc.name;
    return e;
  }
  return {};
}

int nearest_step_value(const ParamDesc& desc, int value) {
  if (!desc.has_step()) return value;
  const long long base = static_cast<long long>(desc.min);
  const long long offset = static_cast<long long>(value) - base;
  // Floor division, then round half up: 4 with steps of 2 from 1 -> 5.
  long long k = offset >= 0 ? offset / desc.step : -((-offset + desc.step - 1) / desc.step);
  if (offset - k * desc.step >= (desc.step + 1) / 2) ++k;
  return static_cast<int>(base + k * desc.step);
}

Result<ParamValue> parse_param_value(const ParamDesc& desc, std::string_view text) {
  std::string s(text);
  auto bad = [&](const char* expected) {
    Error e = make_error("parameter '" + desc.name + "' expects " + expected + ", got '" + shortened(s) + "'");
    e.where = desc.name;
    return e;
  };
  switch (desc.type) {
    case ParamType::boolean:
      if (s == "true" || s == "1" || s == "on") return ParamValue{true};
      if (s == "false" || s == "0" || s == "off") return ParamValue{false};
      return bad("bool (true/false)");
    case ParamType::integer: {
      if (s.empty()) return bad("int");
      char* end = nullptr;
      errno = 0;
      long long v = std::strtoll(s.c_str(), &end, 10);
      if (*end != '\0') return bad("int");
      if (errno == ERANGE || v < INT32_MIN || v > INT32_MAX) {
        Error e = make_error("parameter '" + desc.name + "' = " + shortened(s) + " is out of range " +
                             (desc.has_range() ? range_text(desc) : "of int"));
        e.where = desc.name;
        return e;
      }
      return ParamValue{static_cast<int>(v)};
    }
    case ParamType::real: {
      if (s.empty()) return bad("float");
      char* end = nullptr;
      double v = std::strtod(s.c_str(), &end);
      if (*end != '\0' || !std::isfinite(v)) return bad("float");
      return ParamValue{v};
    }
    case ParamType::enumeration:
      return ParamValue{s};
  }
  return bad("a value");
}

ParameterSet::ParameterSet(std::vector<ParamDesc> descs) : descs_(std::move(descs)) {
  reset_all();
}

const ParamDesc* ParameterSet::find(std::string_view name) const {
  for (const auto& d : descs_)
    if (d.name == name) return &d;
  return nullptr;
}

const ParamValue* ParameterSet::get(std::string_view name) const {
  for (size_t i = 0; i < descs_.size(); ++i)
    if (descs_[i].name == name) return &values_[i];
  return nullptr;
}

bool ParameterSet::get_bool(std::string_view name) const {
  const ParamValue* v = get(name);
  return v && std::holds_alternative<bool>(*v) && std::get<bool>(*v);
}

int ParameterSet::get_int(std::string_view name) const {
  const ParamValue* v = get(name);
  return v && std::holds_alternative<int>(*v) ? std::get<int>(*v) : 0;
}

double ParameterSet::get_real(std::string_view name) const {
  const ParamValue* v = get(name);
  if (!v) return 0.0;
  if (std::holds_alternative<double>(*v)) return std::get<double>(*v);
  if (std::holds_alternative<int>(*v)) return std::get<int>(*v);
  return 0.0;
}

std::string ParameterSet::get_enum(std::string_view name) const {
  const ParamValue* v = get(name);
  return v && std::holds_alternative<std::string>(*v) ? std::get<std::string>(*v) : "";
}

Error ParameterSet::unknown_key_error(std::string_view name) const {
  std::string list;
  for (const auto& d : descs_) list += (list.empty() ? "" : ", ") + d.name;
  Error e = make_error("unknown parameter '" + std::string(name) + "'; valid: " +
                       (list.empty() ? "(none)" : list));
  e.where = std::string(name);
  return e;
}

Status ParameterSet::set(std::string_view name, ParamValue value) {
  for (size_t i = 0; i < descs_.size(); ++i) {
    if (descs_[i].name != name) continue;
    // Store reals as double even when given as an int literal, so readers see one type.
    if (descs_[i].type == ParamType::real && std::holds_alternative<int>(value))
      value = static_cast<double>(std::get<int>(value));
    if (Status s = check_param_value(descs_[i], value); !s) return s;
    values_[i] = std::move(value);
    return {};
  }
  return unknown_key_error(name);
}

Status ParameterSet::set_from_string(std::string_view assignment) {
  size_t eq = assignment.find('=');
  if (eq == std::string_view::npos || eq == 0) {
    Error e = make_error("expected k=v, got '" + shortened(assignment) + "'");
    return e;
  }
  std::string_view key = assignment.substr(0, eq);
  const ParamDesc* desc = find(key);
  if (!desc) return unknown_key_error(key);
  Result<ParamValue> v = parse_param_value(*desc, assignment.substr(eq + 1));
  if (!v) return v.error();
  return set(key, *v);
}

void ParameterSet::reset(std::string_view name) {
  for (size_t i = 0; i < descs_.size(); ++i)
    if (descs_[i].name == name) values_[i] = descs_[i].default_value;
}

void ParameterSet::reset_all() {
  values_.clear();
  for (const auto& d : descs_) values_.push_back(d.default_value);
}

ParamDesc real_param(std::string name, double def, double min, double max, std::string unit,
                     std::string description) {
  ParamDesc d;
  d.name = std::move(name);
  d.type = ParamType::real;
  d.default_value = def;
  d.min = min;
  d.max = max;
  d.unit = std::move(unit);
  d.description = std::move(description);
  return d;
}

ParamDesc int_param(std::string name, int def, int min, int max, std::string unit, std::string description) {
  ParamDesc d = real_param(std::move(name), 0.0, min, max, std::move(unit), std::move(description));
  d.type = ParamType::integer;
  d.default_value = def;
  return d;
}

ParamDesc bool_param(std::string name, bool def, std::string description) {
  ParamDesc d;
  d.name = std::move(name);
  d.type = ParamType::boolean;
  d.default_value = def;
  d.description = std::move(description);
  return d;
}

ParamDesc enum_param(std::string name, std::string def, std::vector<std::string> options,
                     std::string description) {
  ParamDesc d;
  d.name = std::move(name);
  d.type = ParamType::enumeration;
  d.default_value = std::move(def);
  d.options = std::move(options);
  d.description = std::move(description);
  return d;
}

Status check_assignment_keys(const std::string& option, const std::vector<std::string>& assignments) {
  std::map<std::string, std::string> seen;
  for (const std::string& kv : assignments) {
    const std::string key = kv.substr(0, kv.find('='));
    if (auto [it, inserted] = seen.emplace(key, kv); !inserted) {
      Error e = make_error("'" + shortened(key) + "' is given twice (" + shortened(it->second) + ", then " +
                           shortened(kv) + "); give each key once");
      e.where = option + " " + shortened(kv);
      return e;
    }
  }
  return {};
}

}  // namespace penumbra::graph
