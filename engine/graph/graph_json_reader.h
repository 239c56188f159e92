#pragma once
// Internal to the graph_json*.cpp files, which alone read graph files (nlohmann is slow to
// compile: it stays in them and parameters_json.cpp): the state of one parse, and which file
// reads which part. The format is docs/graph-format.md.
//   graph_json.cpp             the document: name, description, resources, outputs; orchestration
//   graph_json_reader.cpp      the reader's primitives: errors, unknown keys, strings, prose
//   graph_json_parameters.cpp  the "parameters" array and the `applies` check
//   graph_json_templates.cpp   "templates" and how a pass's `extends` merges them
//   graph_json_passes.cpp      a pass: its own keys, slot and parameter values
//   graph_json_choices.cpp     {"if"} / {"switch"} values -> bindings under `when` conditions
#include <functional>
#include <initializer_list>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "graph/graph_desc.h"
#include "graph/graph_errors.h"

namespace penumbra::graph::json_detail {

using Json = nlohmann::ordered_json;

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
  void set(const std::string& key, Located value);
  void merge(const LocatedEntries& later);  // set() of each of `later`'s entries, in order
  auto begin() const { return entries_.begin(); }
  auto end() const { return entries_.end(); }

 private:
  std::vector<std::pair<std::string, Located>> entries_;
};

// The part of a pass that a template holds, and that a pass accumulates from its templates
// before its own keys apply (docs/graph-format.md, "Templates").
struct PassShape {
  std::optional<std::string> type;  // the last one given wins
  std::string enabled;  // every one given must hold (condition_and)
  LocatedEntries slots, params;
};

// Turns a plain value of a choice (graph_json_choices.cpp) into one binding under `when`.
using ChoiceLeaf = std::function<void(const Json& value, const std::string& pointer, const std::string& when)>;

class GraphReader {
 public:
  explicit GraphReader(std::string file) : file_(std::move(file)) {}

  // graph_json.cpp
  void read_graph(const Json& root, GraphDesc& g);
  void read_resource(const std::string& name, const Json& j, const std::string& ptr, GraphDesc& g);
  // "tiles": a tile list's or a per-tile texture's tiled area / tile edge, into r.size.
  void parse_tiles(const Json& j, const std::string& ptr, ResourceDecl& r);

  // graph_json_reader.cpp
  void error(GraphErrorCode code, const std::string& pointer, std::string message);
  // Reports keys other than `allowed` (typos would otherwise be silently ignored).
  void check_keys(const Json& obj, const std::string& ptr, std::initializer_list<const char*> allowed);
  bool get_string(const Json& obj, const char* key, const std::string& ptr, std::string& out, bool required);
  // Prose: a string, or an array of strings joined with spaces (keeps lines of a file short).
  void get_text(const Json& obj, const char* key, const std::string& ptr, std::string& out);
  // `enabled`: a condition string, or a bool ("true" / "false"); "" when absent.
  void get_enabled(const Json& obj, const std::string& ptr, std::string& out);
  // Entries of an object-valued key of a pass or template, merged by key into `into`.
  void collect(const Json& obj, const char* key, const std::string& ptr, LocatedEntries& into);

  // graph_json_parameters.cpp
  void read_parameters(const Json& root, GraphDesc& g);
  void read_parameter(const Json& j, const std::string& ptr, GraphDesc& g);
  void check_applies(const GraphDesc& g);

  // graph_json_templates.cpp
  void read_templates(const Json& root);
  // The shape the templates a pass `extends` give it, merged in order.
  PassShape extended_shape(const Json& pass, const std::string& ptr);

  // graph_json_passes.cpp
  void read_pass(const Json& j, const std::string& ptr, GraphDesc& g);
  void read_slot(const std::string& slot, const Located& value, PassDecl& p, const GraphDesc& g);
  void read_param(const std::string& name, const Located& value, PassDecl& p, const GraphDesc& g);

  // graph_json_choices.cpp
  void read_choice(const Json& j, const std::string& ptr, const std::string& when, const GraphDesc& g,
                   const ChoiceLeaf& leaf);
  void read_format(const Json& j, const std::string& ptr, const GraphDesc& g, ResourceDecl& r);
  std::optional<std::string> case_condition(const std::string& param, const std::string& value,
                                            const std::string& ptr, const GraphDesc& g);

  std::string file_;
  GraphErrors errors_;
  std::map<std::string, std::string> param_pointer_;  // parameter name -> "/parameters/N"
  std::map<std::string, PassShape> templates_;        // sorted: the "templates: a, b" hint
};

}  // namespace penumbra::graph::json_detail
