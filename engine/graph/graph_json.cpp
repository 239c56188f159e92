// The only translation unit that reads graph JSON (nlohmann is slow to compile; keep it here
// and in parameters_json.cpp).
#include "graph/graph_json.h"

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "graph/json_values.h"

namespace penumbra::graph {

using Json = nlohmann::ordered_json;

void byte_offset_to_line_col(std::string_view text, size_t offset, int& line, int& column) {
  line = 1;
  column = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
}

namespace {

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
            "unknown key '" + it.key() + "'; expected one of: " + list);
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

  void read_parameter(const Json& j, const std::string& ptr, GraphDesc& g) {
    if (!j.is_object()) {
      error(GraphErrorCode::wrong_json_type, ptr, "a parameter must be an object");
      return;
    }
    size_t before = errors_.size();
    ParamDesc d;
    std::string text;
    get_string(j, "name", ptr, d.name, true);
    if (get_string(j, "type", ptr, text, true)) {
      std::optional<ParamType> t = parse_param_type(text);
      if (!t) error(GraphErrorCode::wrong_json_type, ptr + "/type", "type must be bool, int, float or enum, got \"" + text + "\"");
      else d.type = *t;
    }
    check_keys(j, ptr, {"name", "type", "default", "min", "max", "unit", "description", "structural", "options"});
    get_string(j, "unit", ptr, d.unit, false);
    get_string(j, "description", ptr, d.description, false);
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
    if (auto it = j.find("options"); it != j.end()) {
      if (!it->is_array()) error(GraphErrorCode::wrong_json_type, ptr + "/options", "\"options\" must be an array of strings");
      else
        for (size_t i = 0; i < it->size(); ++i) {
          if ((*it)[i].is_string()) d.options.push_back((*it)[i].get<std::string>());
          else error(GraphErrorCode::wrong_json_type, ptr + "/options/" + std::to_string(i), "option must be a string");
        }
    }
    if (auto it = j.find("default"); it == j.end()) {
      error(GraphErrorCode::wrong_json_type, ptr, "missing \"default\"");
    } else {
      JsonValue v = json_to_param_value(*it);
      if (!v.ok) error(GraphErrorCode::param_wrong_type, ptr + "/default", v.problem);
      else if (Status s = check_param_value(d, v.value); !s)
        error(GraphErrorCode::param_out_of_range, ptr + "/default", s.error().message);
      else d.default_value = d.type == ParamType::real && std::holds_alternative<int>(v.value)
                                 ? ParamValue{static_cast<double>(std::get<int>(v.value))} : v.value;
    }
    if (errors_.size() == before) g.parameters.push_back(std::move(d));
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
      if (!k) error(GraphErrorCode::wrong_json_type, ptr + "/kind", "kind must be texture, buffer, imported or persistent, got \"" + text + "\"");
      else r.kind = *k;
    }
    if (r.kind == ResourceKind::texture || r.kind == ResourceKind::persistent) {
      if (get_string(j, "format", ptr, text, true)) {
        std::optional<Format> f = parse_format(text);
        if (!f) error(GraphErrorCode::wrong_json_type, ptr + "/format", "unknown format \"" + text + "\"; formats: R8, R16F, R32F, RG16F, RG32F, RGBA8, RGBA16F, RGBA32F, DEPTH32F");
        else r.format = *f;
      }
      if (get_string(j, "size", ptr, text, true)) {
        std::optional<SizeExpr> s = SizeExpr::parse(text);
        if (!s) error(GraphErrorCode::wrong_json_type, ptr + "/size", "bad size \"" + text + "\"; expected screen, screen/N, shadow, shadow/N or WxH (1..16384)");
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

  void read_binding(const std::string& slot, const Json& j, const std::string& ptr, PassDecl& p) {
    if (!j.is_string()) {
      error(GraphErrorCode::wrong_json_type, ptr, "slot '" + slot + "' must name a resource (\"name\" or \"name@version\")");
      return;
    }
    SlotBinding b;
    b.slot = slot;
    b.location = ptr;
    std::string text = j.get<std::string>();
    size_t at = text.find('@');
    b.resource = text.substr(0, at);
    if (at != std::string::npos) {
      std::string digits = text.substr(at + 1);
      bool ok = !digits.empty() && digits.size() <= 4 &&
                digits.find_first_not_of("0123456789") == std::string::npos;
      if (!ok || std::stoi(digits) > 1024) {
        error(GraphErrorCode::wrong_json_type, ptr, "bad version in \"" + text + "\"; expected name@N with N in 0..1024");
        return;
      }
      b.version = std::stoi(digits);
    }
    p.slots.push_back(std::move(b));
  }

  void read_pass(const Json& j, const std::string& ptr, GraphDesc& g) {
    if (!j.is_object()) {
      error(GraphErrorCode::wrong_json_type, ptr, "a pass must be an object");
      return;
    }
    PassDecl p;
    p.location = ptr;
    check_keys(j, ptr, {"type", "name", "slots", "params", "enabled", "repeat", "side_effect", "description"});
    get_string(j, "type", ptr, p.type, true);
    get_string(j, "name", ptr, p.name, true);
    if (auto it = j.find("slots"); it != j.end()) {
      if (!it->is_object()) error(GraphErrorCode::wrong_json_type, ptr + "/slots", "\"slots\" must be an object {slot: resource}");
      else for (auto s = it->begin(); s != it->end(); ++s) read_binding(s.key(), s.value(), ptr + "/slots/" + s.key(), p);
    }
    if (auto it = j.find("params"); it != j.end()) {
      if (!it->is_object()) error(GraphErrorCode::wrong_json_type, ptr + "/params", "\"params\" must be an object");
      else
        for (auto s = it->begin(); s != it->end(); ++s) {
          ParamBinding b;
          b.name = s.key();
          b.location = ptr + "/params/" + s.key();
          JsonValue v = json_to_param_value(s.value());
          if (!v.ok) {
            error(v.out_of_range ? GraphErrorCode::param_out_of_range : GraphErrorCode::param_wrong_type,
                  b.location, "pass '" + p.name + "', parameter '" + b.name + "': " + v.problem);
            continue;
          }
          auto* str = std::get_if<std::string>(&v.value);
          if (str && !str->empty() && (*str)[0] == '$') b.reference = str->substr(1);
          else b.constant = v.value;
          p.params.push_back(std::move(b));
        }
    }
    if (auto it = j.find("enabled"); it != j.end()) {
      if (it->is_string()) p.enabled = it->get<std::string>();
      else if (it->is_boolean()) p.enabled = it->get<bool>() ? "true" : "false";
      else error(GraphErrorCode::wrong_json_type, ptr + "/enabled", "\"enabled\" must be a condition string or a bool");
    }
    if (auto it = j.find("repeat"); it != j.end()) {
      if (it->is_string() && it->get<std::string>().size() > 1 && it->get<std::string>()[0] == '$')
        p.repeat_reference = it->get<std::string>().substr(1);
      else if (it->is_number_integer() && it->get<std::int64_t>() >= INT32_MIN && it->get<std::int64_t>() <= INT32_MAX)
        p.repeat = static_cast<int>(it->get<std::int64_t>());
      else if (it->is_number())
        error(GraphErrorCode::repeat_out_of_range, ptr + "/repeat", "pass '" + p.name + "': repeat out of range [1, 64]");
      else
        error(GraphErrorCode::wrong_json_type, ptr + "/repeat", "\"repeat\" must be an integer or \"$param\"");
    }
    if (auto it = j.find("side_effect"); it != j.end()) {
      if (it->is_boolean()) p.side_effect = it->get<bool>();
      else error(GraphErrorCode::wrong_json_type, ptr + "/side_effect", "\"side_effect\" must be true or false");
    }
    g.passes.push_back(std::move(p));
  }

  void read_graph(const Json& root, GraphDesc& g) {
    if (!root.is_object()) {
      error(GraphErrorCode::wrong_json_type, "/", "a graph file must be a JSON object");
      return;
    }
    check_keys(root, "", {"name", "description", "parameters", "resources", "passes", "outputs"});
    get_string(root, "name", "", g.name, false);
    if (auto it = root.find("parameters"); it != root.end()) {
      if (!it->is_array()) error(GraphErrorCode::wrong_json_type, "/parameters", "\"parameters\" must be an array");
      else for (size_t i = 0; i < it->size(); ++i) read_parameter((*it)[i], "/parameters/" + std::to_string(i), g);
    }
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
};

}  // namespace

Checked<GraphDesc> parse_graph_json(std::string_view text, const std::string& file_name) {
  GraphReader reader(file_name);
  auto fail_at = [&](size_t offset, const std::string& message) {
    GraphError e;
    e.code = GraphErrorCode::malformed_json;
    e.file = file_name;
    byte_offset_to_line_col(text, offset, e.line, e.column);
    e.message = message;
    return GraphErrors{e};
  };
  // nlohmann parses recursively: refuse deep nesting before it can exhaust the stack.
  if (size_t offset = 0; json_nesting_exceeds(text, kMaxJsonDepth, offset))
    return fail_at(offset, "nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
  Json root;
  try {
    root = Json::parse(text.begin(), text.end());
  } catch (const Json::parse_error& e) {
    // e.byte is 1-based: the position of the byte that made parsing fail.
    std::string what = e.what();
    size_t cut = what.find("parse error");
    return fail_at(e.byte > 0 ? e.byte - 1 : 0,
                   "malformed JSON: " + (cut == std::string::npos ? what : what.substr(cut)));
  } catch (const std::exception& e) {
    return fail_at(0, std::string("malformed JSON: ") + e.what());
  }
  GraphDesc g;
  g.source_file = file_name;
  try {
    reader.read_graph(root, g);
  } catch (const std::exception& e) {  // defensive: no JSON content may crash the caller
    reader.error(GraphErrorCode::wrong_json_type, "/", std::string("unexpected: ") + e.what());
  }
  if (!reader.errors_.empty()) return reader.errors_;
  return g;
}

Checked<GraphDesc> load_graph_json(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    GraphError e;
    e.code = GraphErrorCode::malformed_json;
    e.file = path;
    e.message = "cannot open file";
    return GraphErrors{e};
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_graph_json(text.str(), path);
}

}  // namespace penumbra::graph
