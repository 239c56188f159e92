// A graph file -> GraphDesc: the document's own keys (name, description, resources, outputs)
// and the order its parts are read in. graph_json_reader.h lists the files that read the rest;
// the format is docs/graph-format.md.
#include "graph/graph_json.h"

#include <algorithm>
#include <cstdint>
#include <string>

#include "graph/graph_json_reader.h"
#include "util/file_read.h"
#include "util/json_text.h"

namespace penumbra::graph {

namespace json_detail {

void GraphReader::parse_tiles(const Json& j, const std::string& ptr, ResourceDecl& r) {
  std::string text;
  if (!get_string(j, "tiles", ptr, text, true)) return;
  std::optional<SizeExpr> s = SizeExpr::parse(text);
  if (!s || s->base == SizeExpr::Base::fixed)
    error(GraphErrorCode::wrong_json_type, ptr + "/tiles", "bad tiles \"" + shortened(text) + "\"; expected screen/N, screen/$param, shadow/N or shadow/$param, N the tile edge in pixels (a power of two in " + std::to_string(kMinTileSize) + ".." + std::to_string(kMaxTileSize) + ")");
  else
    r.size = *s;
}

void GraphReader::read_resource(const std::string& name, const Json& j, const std::string& ptr, GraphDesc& g) {
  ResourceDecl r;
  r.name = name;
  r.location = ptr;
  if (!j.is_object()) {
    error(GraphErrorCode::wrong_json_type, ptr, "a resource must be an object");
    return;
  }
  check_keys(j, ptr, {"kind", "format", "size", "bytes", "tiles", "description"});
  std::string text;
  if (get_string(j, "kind", ptr, text, true)) {
    std::optional<ResourceKind> k = parse_resource_kind(text);
    if (!k) error(GraphErrorCode::wrong_json_type, ptr + "/kind", "kind must be texture, buffer, imported or persistent, got \"" + shortened(text) + "\"");
    else r.kind = *k;
  }
  if (r.kind == ResourceKind::texture || r.kind == ResourceKind::persistent) {
    read_format(j, ptr, g, r);
    if (r.kind == ResourceKind::texture && j.contains("tiles")) {
      r.per_tile = true;
      if (j.contains("size")) error(GraphErrorCode::wrong_json_type, ptr + "/size", "a texture of one texel per tile is sized by its \"tiles\"; \"size\" does not apply");
      parse_tiles(j, ptr, r);
    } else if (get_string(j, "size", ptr, text, true)) {
      std::optional<SizeExpr> s = SizeExpr::parse(text);
      if (!s) error(GraphErrorCode::wrong_json_type, ptr + "/size", "bad size \"" + shortened(text) + "\"; expected screen, screen/N, screen/$param, shadow, shadow/N, shadow/$param (N in 1..64), WxH (1..16384), or \"tiles\" instead of \"size\" (one texel per tile)");
      else r.size = *s;
    }
  } else if (r.kind == ResourceKind::buffer && j.contains("tiles")) {
    r.tile_list = true;
    if (j.contains("bytes")) error(GraphErrorCode::wrong_json_type, ptr + "/bytes", "a tile list's size is its \"tiles\"; \"bytes\" does not apply");
    parse_tiles(j, ptr, r);
  } else if (r.kind == ResourceKind::buffer) {
    auto it = j.find("bytes");
    // 1 GiB: far more than any shadow technique needs; a bigger number is a typo.
    if (it == j.end() || !it->is_number_unsigned() || it->get<std::uint64_t>() == 0 ||
        it->get<std::uint64_t>() > (1ull << 30))
      error(GraphErrorCode::wrong_json_type, ptr + "/bytes", "buffer needs \"bytes\", an integer in 1..1073741824, or \"tiles\" (a tile list, docs/graph-format.md)");
    else r.bytes = it->get<std::uint64_t>();
  }
  g.resources.push_back(std::move(r));
}

// "format": a name, "$param" (an enum parameter whose options are format names), or a choice
// ({"if"} / {"switch"}) of names: docs/graph-format.md, "Resources".
void GraphReader::read_format(const Json& j, const std::string& ptr, const GraphDesc& g, ResourceDecl& r) {
  const std::string at = ptr + "/format";
  auto it = j.find("format");
  if (it == j.end()) {
    error(GraphErrorCode::wrong_json_type, ptr, "missing \"format\" (string)");
    return;
  }
  auto leaf = [&](const Json& v, const std::string& p, const std::string& when) {
    std::optional<Format> f = v.is_string() ? parse_format(v.get<std::string>()) : std::nullopt;
    if (!f) {
      error(GraphErrorCode::wrong_json_type, p, "unknown format " + shortened(v.dump()) + "; formats: " + format_names());
      return;
    }
    r.format_choices.push_back({when, *f});
  };
  if (it->is_string() && it->get<std::string>().rfind("$", 0) == 0) {
    const std::string name = it->get<std::string>().substr(1);
    const auto d = std::find_if(g.parameters.begin(), g.parameters.end(), [&](const ParamDesc& p) { return p.name == name; });
    if (d == g.parameters.end() || d->type != ParamType::enumeration) {
      error(d == g.parameters.end() ? GraphErrorCode::unknown_param_reference : GraphErrorCode::param_wrong_type, at,
            "format \"$" + shortened(name) + "\" needs an enum parameter '" + shortened(name) +
                "' whose options are format names" + (d == g.parameters.end() ? "; there is none" : "; it is not an enum"));
      return;
    }
    for (size_t i = 0; i < d->options.size(); ++i)
      leaf(Json(d->options[i]), at, "$" + name + " == \"" + d->options[i] + "\"");
  } else if (it->is_object()) {
    read_choice(*it, at, "", g, leaf);
  } else {
    leaf(*it, at, "");
  }
  // A fixed format needs no choosing: the one case that always holds.
  if (r.format_choices.size() == 1 && r.format_choices[0].when.empty()) {
    r.format = r.format_choices[0].format;
    r.format_choices.clear();
  } else if (!r.format_choices.empty()) {
    r.format = r.format_choices[0].format;
  }
}

// Parameters first (choices and `applies` look them up), then templates (passes extend them).
void GraphReader::read_graph(const Json& root, GraphDesc& g) {
  if (!root.is_object()) {
    error(GraphErrorCode::wrong_json_type, "/", "a graph file must be a JSON object");
    return;
  }
  check_keys(root, "", {"name", "description", "parameters", "templates", "resources", "passes", "outputs"});
  get_string(root, "name", "", g.name, false);
  get_text(root, "description", "", g.description);
  read_parameters(root, g);
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

}  // namespace json_detail

Checked<GraphDesc> parse_graph_json(std::string_view text, const std::string& file_name) {
  using json_detail::Json;
  json_detail::GraphReader reader(file_name);
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
  if (std::optional<JsonTextProblem> p = scan_json_text(text))
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
