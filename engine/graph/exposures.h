#pragma once
// Exposed parameters (graph_desc.h ParamExposure): a graph parameter declared with
// "exposes": "pass.param" takes its description from the pass type and states only what it
// changes. resolve_exposures() fills the description in; it runs once after parsing, before a
// ParameterSet is made from the graph's parameters (the sandbox, the CLI's --set and presets
// read the resolved descriptions), and compile() refuses a graph whose exposures it did not see.
//
//   Checked<GraphDesc> g = parse_graph_json(text, "pmchss.json");
//   GraphErrors errors = resolve_exposures(*g, library.declarations());
//   ParameterSet params(g->parameters);
#include "graph/graph_desc.h"
#include "graph/graph_errors.h"
#include "graph/pass_types.h"

namespace penumbra::graph {

// Every problem at once, each naming the "exposes" key's JSON pointer: a pass the graph does
// not declare, a parameter its type does not declare, a stated type that differs, a stated
// range wider than the pass type's, options it lacks, and a stated field equal to the one it
// would inherit (the description would then be written twice). A pass of an unknown type is
// left to compile(), which reports it.
GraphErrors resolve_exposures(GraphDesc& graph, const PassTypeRegistry& registry);

}  // namespace penumbra::graph
