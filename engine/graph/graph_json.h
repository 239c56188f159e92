#pragma once
// JSON graph files -> GraphDesc (the format is documented in docs/graph-format.md).
// Never throws and never crashes on any input: malformed JSON gives one error with line and
// column; everything else gives every error found, each with a JSON pointer.
#include <string>
#include <string_view>

#include "graph/graph_desc.h"
#include "graph/graph_errors.h"

namespace penumbra::graph {

Checked<GraphDesc> parse_graph_json(std::string_view text, const std::string& file_name = "");
Checked<GraphDesc> load_graph_json(const std::string& path);

}  // namespace penumbra::graph
