// The only translation unit that reads graph JSON (nlohmann is slow to compile; keep it here
// and in parameters_json.cpp). The format is docs/graph-format.md.
#include "graph/graph_json.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "graph/condition.h"
#include "graph/json_values.h"
#include "util/file_read.h"
#include "util/json_text.h"

namespace penumbra::graph {

using Json = nlohmann::ordered_json;

namespace {

// A value as written in the file, with its JSON pointer.
struct Located {
  const Json* value;
  std::string pointer;
};

// Slots or parameters of a pass merged from its templates and its own keys: a later entry
// replaces an earlier one of the same key in place, so the file's order is kept (binding order
// decides version numbering ties, and the golden plans).
class LocatedEntries {
 public:
  void set(const std::string& key, Located value) {
    for (auto& [k, v] : entries_)
      if (k == key) {
        v = std::move(value);
        return;
      }
    entries_.emplace_back(key, std::move(value));
  }
  auto begin() const { return entries_.begin(); }
  auto end() const { return entries_.end(); }

 private:
  std::vector<std::pair<std::string, Located>> entries_;
};

class GraphReader {
 public:
  GraphReader(std::string file) : file_(std::move(file)) {}

  void error(GraphErrorCode code, const std::string& pointer, std::string message) {
    GraphError e;
    e.code = code;
    e.file = file_;
    e.where = pointer.empty() ? "/" : pointer;
    e.message = std::move(message);
    errors_.push_back(std::move(e));
  }

  // Reports keys other than `allowed` (typos would otherwise be silently ignored).
  void check_keys(const Json& obj, const std::string& ptr, std::initializer_list<const char*> allowed) {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || it.key() == a;
      if (ok) continue;
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      error(GraphErrorCode::wrong_json_type, ptr + "/" + it.key(),
            "unknown key '" + shortened(it.key()) + "'; expected one of: " + list);
    }
  }

  bool get_string(const Json& obj, const char* key, const std::string& ptr, std::string& out, bool required) {
    auto it = obj.find(key);
    if (it == obj.end()) {
      if (required) error(GraphErrorCode::wrong_json_type, ptr, std::string("missing \"") + key + "\" (string)");
      return false;
    }
    if (!it->is_string()) {
      error(GraphErrorCode::wrong_json_type, ptr + "/" + key,
            std::string("\"") + key + "\" must be a string, got " + it->type_name());
      return false;
    }
    out = it->get<std::string>();
    return true;
  }

  // Prose: a string, or an array of strings joined with spaces (keeps lines of a file short).
  void get_text(const Json& obj, const char* key, const std::string& ptr, std::string& out) {
    auto it = obj.find(key);
    if (it == obj.end()) return;
    if (it->is_string()) {
      out = it->get<std::string>();
      return;
    }
    bool lines = it->is_array();
    for (const Json& line : *it) lines = lines && line.is_string();
    if (!lines) {
      error(GraphErrorCode::wrong_json_type, ptr + "/" + key,
            std::string("\"") + key + "\" must be a string or an array of strings");
      return;
    }
    out.clear();
    for (const Json& line : *it) out += (out.empty() ? "" : " ") + line.get<std::string>();
  }

  // A parameter is described in full, or exposes a pass parameter ("exposes": "pass.param") and
  // states only what it changes; resolve_exposures() (exposures.h) fills in the rest.
  void read_parameter(const Json& j, const std::string& ptr, GraphDesc& g) {
    if (!j.is_object()) {
      error(GraphErrorCode::wrong_json_type, ptr, "a parameter must be an object");
      return;
    }
    size_t before = errors_.size();
    ParamDesc d;
    ParamExposure exposure;
    std::string text;
    get_string(j, "name", ptr, d.name, true);
    const bool exposes = j.contains("exposes");
    if (exposes && get_string(j, "exposes", ptr, text, true)) {
      const size_t dot = text.rfind('.');
      if (dot == std::string::npos || dot == 0 || dot + 1 == text.size())
        error(GraphErrorCode::wrong_json_type, ptr + "/exposes",
              "\"exposes\" must be \"pass.parameter\", got \"" + shortened(text) + "\"");
      else {
        exposure.pass = text.substr(0, dot);
        exposure.pass_param = text.substr(dot + 1);
      }
    }
    StatedFields& stated = exposure.stated;
    stated = {j.contains("type"),        j.contains("default"), j.contains("min"),     j.contains("max"),
              j.contains("unit"),        j.contains("description"), j.contains("options"), j.contains("step")};
    if (get_string(j, "type", ptr, text, !exposes)) {
      std::optional<ParamType> t = parse_param_type(text);
      if (!t) error(GraphErrorCode::wrong_json_type, ptr + "/type", "type must be bool, int, float or enum, got \"" + shortened(text) + "\"");
      else d.type = *t;
    }
    check_keys(j, ptr, {"name", "type", "default", "min", "max", "step", "unit", "description", "structural", "options",
                        "applies", "exposes"});
    get_string(j, "unit", ptr, d.unit, false);
    get_text(j, "description", ptr, d.description);
    if (auto it = j.find("structural"); it != j.end()) {
      if (it->is_boolean()) d.structural = it->get<bool>();
      else error(GraphErrorCode::wrong_json_type, ptr + "/structural", "\"structural\" must be true or false");
    }
    for (const char* key : {"min", "max"}) {
      auto it = j.find(key);
      if (it == j.end()) continue;
      if (!it->is_number() || !std::isfinite(it->get<double>()))
        error(GraphErrorCode::wrong_json_type, ptr + "/" + key, std::string("\"") + key + "\" must be a finite number");
      else (std::string(key) == "min" ? d.min : d.max) = it->get<double>();
    }
    if (auto it = j.find("step"); it != j.end()) {
      if ((stated.type && d.type != ParamType::integer) || !it->is_number_integer() || it->get<long long>() < 1 ||
          it->get<long long>() > 1000000)
        error(GraphErrorCode::wrong_json_type, ptr + "/step",
              "\"step\" must be an integer in 1..1000000, on an int parameter (valid values: min + k * step)");
      else d.step = it->get<int>();
    }
    get_text(j, "applies", ptr, d.applies);
    if (auto it = j.find("options"); it != j.end()) {
      if (!it->is_array()) error(GraphErrorCode::wrong_json_type, ptr + "/options", "\"options\" must be an array of strings");
      else
        for (size_t i = 0; i < it->size(); ++i) {
          if ((*it)[i].is_string()) d.options.push_back((*it)[i].get<std::string>());
          else error(GraphErrorCode::wrong_json_type, ptr + "/options/" + std::to_string(i), "option must be a string");
        }
    }
    if (auto it = j.find("default"); it == j.end()) {
      if (!exposes) error(GraphErrorCode::wrong_json_type, ptr, "missing \"default\"");
    } else {
      JsonValue v = json_to_param_value(*it);
      if (!v.ok) error(GraphErrorCode::param_wrong_type, ptr + "/default", v.problem);
      else if (!stated.type) d.default_value = v.value;  // typed and range-checked when resolved
      else if (Status s = check_param_value(d, v.value); !s)
        error(GraphErrorCode::param_out_of_range, ptr + "/default", s.error().message);
      else d.default_value = d.type == ParamType::real && std::holds_alternative<int>(v.value)
                                 ? ParamValue{static_cast<double>(std::get<int>(v.value))} : v.value;
    }
    if (errors_.size() != before) return;
    for (const ParamDesc& other : g.parameters)
      if (other.name == d.name) {
        error(GraphErrorCode::duplicate_name, ptr + "/name",
              "parameter '" + shortened(d.name) + "' is declared twice (also at " + param_pointer_[d.name] +
                  "); one of them could never be set");
        return;
      }
    param_pointer_[d.name] = ptr;
    if (exposes) {
      exposure.parameter = d.name;
      exposure.location = ptr + "/exposes";
      g.exposures.push_back(std::move(exposure));
    }
    g.parameters.push_back(std::move(d));
  }

  // "applies" conditions, once every parameter is known. Unlike `enabled`, they may read
  // non-structural parameters: they only tell a UI whether a value has an effect.
  void check_applies(const GraphDesc& g) {
    std::vector<ParamDesc> readable = g.parameters;
    for (ParamDesc& d : readable) d.structural = true;  // so check() reports only real problems
    const ParameterSet params(std::move(readable));
    for (const ParamDesc& d : g.parameters) {
      if (d.applies.empty()) continue;
      const std::string where = param_pointer_[d.name] + "/applies";
      Result<Condition> c = Condition::parse(d.applies);
      if (!c) {
        error(GraphErrorCode::bad_condition, where, "parameter '" + d.name + "': " + c.error().message);
        continue;
      }
      // A parameter whose type comes from the pass it exposes is typed only once resolved:
      // resolve_exposures() checks the conditions that read one.
      const bool reads_untyped = std::any_of(c->references().begin(), c->references().end(), [&](const std::string& r) {
        return std::any_of(g.exposures.begin(), g.exposures.end(),
                           [&](const ParamExposure& e) { return e.parameter == r && !e.stated.type; });
      });
      if (reads_untyped) continue;
      if (std::optional<ConditionProblem> p = c->check(params))
        error(p->kind == ConditionProblem::Kind::unknown_parameter ? GraphErrorCode::unknown_param_reference
                                                                   : GraphErrorCode::bad_condition,
              where, "parameter '" + d.name + "': " + p->message);
    }
  }

  void read_resource(const std::string& name, const Json& j, const std::string& ptr, GraphDesc& g) {
    ResourceDecl r;
    r.name = name;
    r.location = ptr;
    if (!j.is_object()) {
      error(GraphErrorCode::wrong_json_type, ptr, "a resource must be an object");
      return;
    }
    check_keys(j, ptr, {"kind", "format", "size", "bytes", "description"});
    std::string text;
    if (get_string(j, "kind", ptr, text, true)) {
      std::optional<ResourceKind> k = parse_resource_kind(text);
      if (!k) error(GraphErrorCode::wrong_json_type, ptr + "/kind", "kind must be texture, buffer, imported or persistent, got \"" + shortened(text) + "\"");
      else r.kind = *k;
    }
    if (r.kind == ResourceKind::texture || r.kind == ResourceKind::persistent) {
      if (get_string(j, "format", ptr, text, true)) {
        std::optional<Format> f = parse_format(text);
        if (!f) error(GraphErrorCode::wrong_json_type, ptr + "/format", "unknown format \"" + shortened(text) + "\"; formats: R8, R16F, R32F, RG16F, RG32F, RGBA8, RGBA16F, RGBA32F, DEPTH32F");
        else r.format = *f;
      }
      if (get_string(j, "size", ptr, text, true)) {
        std::optional<SizeExpr> s = SizeExpr::parse(text);
        if (!s) error(GraphErrorCode::wrong_json_type, ptr + "/size", "bad size \"" + shortened(text) + "\"; expected screen, screen/N, screen/$param, shadow, shadow/N, shadow/$param (N in 1..64) or WxH (1..16384)");
        else r.size = *s;
      }
    } else if (r.kind == ResourceKind::buffer) {
      auto it = j.find("bytes");
      // 1 GiB: far more than any shadow technique needs; a bigger number is a typo.
      if (it == j.end() || !it->is_number_unsigned() || it->get<std::uint64_t>() == 0 ||
          it->get<std::uint64_t>() > (1ull << 30))
        error(GraphErrorCode::wrong_json_type, ptr + "/bytes", "buffer needs \"bytes\": an integer in 1..1073741824");
      else r.bytes = it->get<std::uint64_t>();
    }
    g.resources.push_back(std::move(r));
  }

  // The condition text a `switch` case stands for: `$p == "case"` for an enum (or a string),
  // `$p == 3` for an int, `$p == true` for a bool, by the parameter's declared type.
  std::optional<std::string> case_condition(const std::string& param, const std::string& value,
                                            const std::string& ptr, const GraphDesc& g) {
    for (const ParamDesc& d : g.parameters) {
      if (d.name != param) continue;
      if (d.type == ParamType::integer) {
        bool digits = !value.empty() && value.find_first_not_of("-0123456789") == std::string::npos && value.size() < 11;
        if (digits) return "$" + param + " == " + value;
      } else if (d.type == ParamType::boolean) {
        if (value == "true" || value == "false") return "$" + param + " == " + value;
      } else if (value.find('"') == std::string::npos) {
        return "$" + param + " == \"" + value + "\"";
      }
      error(GraphErrorCode::bad_condition, ptr,
            "case \"" + shortened(value) + "\" is not a value of '$" + param + "' (" + param_type_name(d.type) + ")");
      return std::nullopt;
    }
    error(GraphErrorCode::unknown_param_reference, ptr, "switch on '$" + shortened(param) + "', which is not a parameter of this graph");
    return std::nullopt;
  }

  // A slot's or parameter's value: a plain value, or a choice by condition that expands into
  // bindings with `when` (graph_desc.h's binding rule: the first applying binding wins):
  //   {"if": "COND", "then": V, "else": V}           else optional
  //   {"switch": "$p", "cases": {"a": V, ...}, "default": V}   default optional
  // V is a plain value, null (unbound) or another choice. `leaf` turns a plain value into one
  // binding under a condition.
  template <class Leaf>
  void read_choice(const Json& j, const std::string& ptr, const std::string& when, const GraphDesc& g, Leaf leaf) {
    if (!j.is_object()) {
      leaf(j, ptr, when);
      return;
    }
    auto negated = [&](const std::string& c) { return condition_and(when, "!(" + c + ")"); };
    if (j.contains("if")) {
      check_keys(j, ptr, {"if", "then", "else"});
      auto cond = j.find("if");
      auto then = j.find("then");
      if (!cond->is_string() || then == j.end()) {
        error(GraphErrorCode::wrong_json_type, ptr, "a choice is {\"if\": \"condition\", \"then\": value, \"else\": value}");
        return;
      }
      const std::string c = cond->get<std::string>();
      read_choice(*then, ptr + "/then", condition_and(when, c), g, leaf);
      if (auto e = j.find("else"); e != j.end()) read_choice(*e, ptr + "/else", negated(c), g, leaf);
      return;
    }
    if (j.contains("switch")) {
      check_keys(j, ptr, {"switch", "cases", "default"});
      auto on = j.find("switch");
      auto cases = j.find("cases");
      if (!on->is_string() || on->get<std::string>().size() < 2 || on->get<std::string>()[0] != '$' ||
          cases == j.end() || !cases->is_object()) {
        error(GraphErrorCode::wrong_json_type, ptr, "a switch is {\"switch\": \"$param\", \"cases\": {\"value\": ...}, \"default\": ...}");
        return;
      }
      const std::string param = on->get<std::string>().substr(1);
      std::string none_matched;
      for (auto c = cases->begin(); c != cases->end(); ++c) {
        std::optional<std::string> cond = case_condition(param, c.key(), ptr + "/cases/" + c.key(), g);
        if (!cond) continue;
        read_choice(c.value(), ptr + "/cases/" + c.key(), condition_and(when, *cond), g, leaf);
        none_matched = condition_and(none_matched, "!(" + *cond + ")");
      }
      if (auto d = j.find("default"); d != j.end()) read_choice(*d, ptr + "/default", condition_and(when, none_matched), g, leaf);
      return;
    }
    error(GraphErrorCode::wrong_json_type, ptr,
          "expected a value, or a choice {\"if\": ...} / {\"switch\": ...}");
  }

  void read_slot(const std::string& slot, const Located& value, PassDecl& p, const GraphDesc& g) {
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

  void read_param(const std::string& name, const Located& value, PassDecl& p, const GraphDesc& g) {
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

  // Entries of an object-valued key of a pass or template, merged by key into `into`.
  void collect(const Json& obj, const char* key, const std::string& ptr, LocatedEntries& into) {
    auto it = obj.find(key);
    if (it == obj.end()) return;
    if (!it->is_object()) {
      error(GraphErrorCode::wrong_json_type, ptr + "/" + key, std::string("\"") + key + "\" must be an object");
      return;
    }
    for (auto e = it->begin(); e != it->end(); ++e) into.set(e.key(), {&e.value(), ptr + "/" + key + "/" + e.key()});
  }

  // The templates a pass extends, in order ("extends": "name" or ["a", "b"]).
  std::vector<const Json*> extended_templates(const Json& j, const std::string& ptr) {
    std::vector<const Json*> out;
    auto it = j.find("extends");
    if (it == j.end()) return out;
    std::vector<Json> names = it->is_array() ? it->get<std::vector<Json>>() : std::vector<Json>{*it};
    for (const Json& n : names) {
      if (!n.is_string()) {
        error(GraphErrorCode::wrong_json_type, ptr + "/extends", "\"extends\" must be a template name or an array of them");
        continue;
      }
      auto t = templates_.find(n.get<std::string>());
      if (t == templates_.end()) {
        std::string known;
        for (const auto& [name, unused] : templates_) known += (known.empty() ? "" : ", ") + name;
        error(GraphErrorCode::wrong_json_type, ptr + "/extends",
              "no template named '" + shortened(n.get<std::string>()) + "'; templates: " + (known.empty() ? "(none)" : known));
        continue;
      }
      out.push_back(t->second.value);
    }
    return out;
  }

  void read_pass(const Json& j, const std::string& ptr, GraphDesc& g) {
    if (!j.is_object()) {
      error(GraphErrorCode::wrong_json_type, ptr, "a pass must be an object");
      return;
    }
    PassDecl p;
    p.location = ptr;
    check_keys(j, ptr, {"type", "name", "extends", "slots", "params", "enabled", "repeat", "side_effect", "description"});
    LocatedEntries slots, params;
    for (const Json* t : extended_templates(j, ptr)) {
      const std::string tptr = templates_pointer_.at(t);
      if (auto type = t->find("type"); type != t->end() && type->is_string()) p.type = type->get<std::string>();
      if (auto e = t->find("enabled"); e != t->end() && e->is_string()) p.enabled = e->get<std::string>();
      collect(*t, "slots", tptr, slots);
      collect(*t, "params", tptr, params);
    }
    get_string(j, "type", ptr, p.type, p.type.empty());
    get_string(j, "name", ptr, p.name, true);
    collect(j, "slots", ptr, slots);
    collect(j, "params", ptr, params);
    for (const auto& [slot, value] : slots) read_slot(slot, value, p, g);
    for (const auto& [name, value] : params) read_param(name, value, p, g);
    if (auto it = j.find("enabled"); it != j.end()) {
      // A pass's own condition narrows its templates' (both must hold).
      if (it->is_string()) p.enabled = condition_and(p.enabled, it->get<std::string>());
      else if (it->is_boolean()) p.enabled = condition_and(p.enabled, it->get<bool>() ? "true" : "false");
      else error(GraphErrorCode::wrong_json_type, ptr + "/enabled", "\"enabled\" must be a condition string or a bool");
    }
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

  void read_templates(const Json& root) {
    auto it = root.find("templates");
    if (it == root.end()) return;
    if (!it->is_object()) {
      error(GraphErrorCode::wrong_json_type, "/templates", "\"templates\" must be an object {name: {\"slots\": ..., \"params\": ...}}");
      return;
    }
    for (auto t = it->begin(); t != it->end(); ++t) {
      const std::string ptr = "/templates/" + t.key();
      if (!t->is_object()) {
        error(GraphErrorCode::wrong_json_type, ptr, "a template must be an object");
        continue;
      }
      check_keys(*t, ptr, {"type", "enabled", "slots", "params", "description"});
      templates_[t.key()] = {&t.value(), ptr};
      templates_pointer_[&t.value()] = ptr;
    }
  }

  void read_graph(const Json& root, GraphDesc& g) {
    if (!root.is_object()) {
      error(GraphErrorCode::wrong_json_type, "/", "a graph file must be a JSON object");
      return;
    }
    check_keys(root, "", {"name", "description", "parameters", "templates", "resources", "passes", "outputs"});
    get_string(root, "name", "", g.name, false);
    get_text(root, "description", "", g.description);
    if (auto it = root.find("parameters"); it != root.end()) {
      if (!it->is_array()) error(GraphErrorCode::wrong_json_type, "/parameters", "\"parameters\" must be an array");
      else for (size_t i = 0; i < it->size(); ++i) read_parameter((*it)[i], "/parameters/" + std::to_string(i), g);
      check_applies(g);
    }
    read_templates(root);
    if (auto it = root.find("resources"); it != root.end()) {
      if (!it->is_object()) error(GraphErrorCode::wrong_json_type, "/resources", "\"resources\" must be an object {name: {...}}");
      else for (auto r = it->begin(); r != it->end(); ++r) read_resource(r.key(), r.value(), "/resources/" + r.key(), g);
    }
    if (auto it = root.find("passes"); it == root.end() || !it->is_array()) {
      error(GraphErrorCode::wrong_json_type, "/passes", "\"passes\" must be an array");
    } else {
      for (size_t i = 0; i < it->size(); ++i) read_pass((*it)[i], "/passes/" + std::to_string(i), g);
    }
    if (auto it = root.find("outputs"); it != root.end()) {
      if (!it->is_array()) error(GraphErrorCode::wrong_json_type, "/outputs", "\"outputs\" must be an array of resource names");
      else
        for (size_t i = 0; i < it->size(); ++i) {
          if ((*it)[i].is_string()) g.outputs.push_back((*it)[i].get<std::string>());
          else error(GraphErrorCode::wrong_json_type, "/outputs/" + std::to_string(i), "an output must be a resource name");
        }
    }
  }

  std::string file_;
  GraphErrors errors_;
  std::map<std::string, std::string> param_pointer_;
  std::map<std::string, Located> templates_;
  std::map<const Json*, std::string> templates_pointer_;
};

}  // namespace

Checked<GraphDesc> parse_graph_json(std::string_view text, const std::string& file_name) {
  GraphReader reader(file_name);
  auto fail_at = [&](int line, int column, const std::string& message) {
    GraphError e;
    e.code = GraphErrorCode::malformed_json;
    e.file = file_name;
    e.line = line;
    e.column = column;
    e.message = message;
    return GraphErrors{e};
  };
  // Before nlohmann (which recurses, and keeps the last of two equal keys) sees the text.
  if (std::optional<JsonTextProblem> p = scan_json_text(text, kMaxJsonDepth))
    return fail_at(p->line, p->column, p->message);
  Json root;
  try {
    root = Json::parse(text.begin(), text.end());
  } catch (const Json::parse_error& e) {
    // e.byte is 1-based: the position of the byte that made parsing fail.
    std::string what = e.what();
    size_t cut = what.find("parse error");
    int line = 0, column = 0;
    byte_offset_to_line_col(text, e.byte > 0 ? e.byte - 1 : 0, line, column);
    return fail_at(line, column, "malformed JSON: " + shortened(cut == std::string::npos ? what : what.substr(cut), 200));
  } catch (const std::exception& e) {
    return fail_at(1, 1, std::string("malformed JSON: ") + shortened(e.what(), 200));
  }
  GraphDesc g;
  g.source_file = file_name;
  try {
    reader.read_graph(root, g);
  } catch (const std::exception& e) {  // defensive: no JSON content may crash the caller
    reader.error(GraphErrorCode::wrong_json_type, "/", std::string("unexpected: ") + shortened(e.what(), 200));
  }
  if (!reader.errors_.empty()) return reader.errors_;
  return g;
}

Checked<GraphDesc> load_graph_json(const std::string& path) {
  Result<std::string> text = read_file_whole(path);
  if (!text) {
    GraphError e;
    e.code = GraphErrorCode::malformed_json;
    e.file = path;
    e.message = text.error().message;
    return GraphErrors{e};
  }
  return parse_graph_json(*text, path);
}

}  // namespace penumbra::graph
