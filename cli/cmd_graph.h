#pragma once
// `penumbra graph FILE.json [--plan] [--traffic] [--json OUT] [--dot OUT] [--screen WxH] ...`
// Compiles a graph file against cli_pass_library() and prints the plan or its traffic, writes
// JSON / Graphviz.
// args exclude "penumbra graph". Exit codes: 0 ok, 2 invalid input (every error on stderr,
// one per line, "file:line:col: where: message"), 1 internal error.
#include <string>
#include <vector>

namespace penumbra::cli {

int cmd_graph(const std::vector<std::string>& args);

}  // namespace penumbra::cli
