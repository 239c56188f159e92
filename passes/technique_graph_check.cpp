#include "passes/technique_graph_check.h"

#include "graph/compiler.h"
#include "graph/parameters.h"
#include "passes/shared_passes.h"
#include "technique/frame_graph.h"

namespace penumbra {

std::vector<Error> technique_graph_errors(const technique::TechniqueRegistry& registry,
                                          const technique::Technique& technique) {
  const exec::PassLibrary library = make_pass_library(registry);
  Result<graph::GraphDesc> declared = technique::load_technique_graph(technique, library.declarations());
  if (!declared) return {declared.error()};
  Result<graph::GraphDesc> frame = technique::compose_frame_graph(*declared);
  if (!frame) return {frame.error()};
  const graph::ParameterSet defaults(frame->parameters);
  auto plan = graph::compile(*frame, library.declarations(), defaults, graph::CompileSettings{});
  if (plan) return {};
  std::vector<Error> errors;
  for (const graph::GraphError& e : plan.errors()) {
    errors.push_back(e);
    if (errors.back().file.empty()) errors.back().file = technique.graph_file;
  }
  return errors;
}

}  // namespace penumbra
