// The graph reader's primitives, shared by every graph_json*.cpp: errors with JSON pointers,
// unknown keys, strings, prose, `enabled`, and object-valued keys collected as entries.
#include "graph/graph_json_reader.h"

namespace penumbra::graph::json_detail {

void LocatedEntries::set(const std::string& key, Located value) {
  for (auto& [k, v] : entries_)
    if (k == key) {
      v = std::move(value);
      return;
    }
  entries_.emplace_back(key, std::move(value));
}

void LocatedEntries::merge(const LocatedEntries& later) {
  for (const auto& [key, value] : later) set(key, value);
}

void GraphReader::error(GraphErrorCode code, const std::string& pointer, std::string message) {
  GraphError e;
  e.code = code;
  e.file = file_;
  e.where = pointer.empty() ? "/" : pointer;
  e.message = std::move(message);
  errors_.push_back(std::move(e));
}

void GraphReader::check_keys(const Json& obj, const std::string& ptr, std::initializer_list<const char*> allowed) {
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

bool GraphReader::get_string(const Json& obj, const char* key, const std::string& ptr, std::string& out, bool required) {
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

void GraphReader::get_text(const Json& obj, const char* key, const std::string& ptr, std::string& out) {
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
  for (const Json& line : *it) {
    if (!out.empty()) out += ' ';
    out += line.get<std::string>();
  }
}

void GraphReader::get_enabled(const Json& obj, const std::string& ptr, std::string& out) {
  auto it = obj.find("enabled");
  if (it == obj.end()) return;
  if (it->is_string()) out = it->get<std::string>();
  else if (it->is_boolean()) out = it->get<bool>() ? "true" : "false";
  else error(GraphErrorCode::wrong_json_type, ptr + "/enabled", "\"enabled\" must be a condition string or a bool");
}

void GraphReader::collect(const Json& obj, const char* key, const std::string& ptr, LocatedEntries& into) {
  auto it = obj.find(key);
  if (it == obj.end()) return;
  if (!it->is_object()) {
    error(GraphErrorCode::wrong_json_type, ptr + "/" + key, std::string("\"") + key + "\" must be an object");
    return;
  }
  for (auto e = it->begin(); e != it->end(); ++e) into.set(e.key(), {&e.value(), ptr + "/" + key + "/" + e.key()});
}

}  // namespace penumbra::graph::json_detail
