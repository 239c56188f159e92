#pragma once
// Shared helpers of the graph tests: the generic registry and a tiny graph builder shortcut.
#include "graph/builder.h"
#include "graph/compiler.h"
#include "support/generic_pass_types.h"

namespace penumbra::graph::testing {

inline const PassTypeRegistry& generic_registry() {
  static const PassTypeRegistry registry = [] {
    PassTypeRegistry r;
    register_generic_pass_types(r);
    return r;
  }();
  return registry;
}

inline CompileSettings small_settings() { return {256, 128, 512}; }

inline Checked<CompiledPlan> compile_graph(const GraphDesc& g, const CompileOptions& options = {}) {
  ParameterSet params(g.parameters);
  return compile(g, generic_registry(), params, small_settings(), options);
}

inline bool has_code(const GraphErrors& errors, GraphErrorCode code) {
  for (const auto& e : errors)
    if (e.code == code) return true;
  return false;
}

inline std::string all_messages(const GraphErrors& errors) {
  std::string out;
  for (const auto& e : errors) out += e.to_string() + "\n";
  return out;
}

inline int position_of(const CompiledPlan& plan, const std::string& pass) {
  for (size_t i = 0; i < plan.passes.size(); ++i)
    if (plan.passes[i].name == pass) return static_cast<int>(i);
  return -1;
}

}  // namespace penumbra::graph::testing
