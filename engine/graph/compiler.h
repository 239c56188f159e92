#pragma once
// compile(): a declared graph (GraphDesc, from JSON or the builder) + pass type registry +
// technique parameter values + sizes -> CompiledPlan, or every error found.
//
//   Checked<GraphDesc> graph = parse_graph_json(text, "pcss.json");      // graph_json.h
//   ParameterSet params(graph->parameters);
//   Checked<CompiledPlan> plan = compile(*graph, registry, params, {1280, 720, 2048});
//   if (!plan) for (const auto& e : plan.errors()) std::cerr << e.to_string() << "\n";
//   else std::cout << to_text(*plan);
//
// compile() is a pipeline of stages, one function per file; compile.cpp is their one list, in
// order, each with the one thing it decides.
#include "graph/graph_desc.h"
#include "graph/graph_errors.h"
#include "graph/pass_types.h"
#include "graph/plan.h"

namespace penumbra::graph {

Checked<CompiledPlan> compile(const GraphDesc& graph, const PassTypeRegistry& registry,
                              const ParameterSet& params, const CompileSettings& settings,
                              const CompileOptions& options = {});

}  // namespace penumbra::graph
