// Graph files: parse, then compile against the generic pass types with the graph's defaults and
// with every structural parameter flipped, at two sizes. Any crash, hang, leak or UB is a bug;
// errors are the expected answer to most inputs.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "graph/compiler.h"
#include "graph/graph_json.h"
#include "support/generic_pass_types.h"

namespace {

const penumbra::graph::PassTypeRegistry& registry() {
  static const penumbra::graph::PassTypeRegistry r = [] {
    penumbra::graph::PassTypeRegistry out;
    penumbra::graph::register_generic_pass_types(out);
    return out;
  }();
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace penumbra::graph;
  auto graph = parse_graph_json(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
  if (!graph) return 0;
  ParameterSet params(graph->parameters);
  (void)compile(*graph, registry(), params, {64, 32, 128});
  for (const ParamDesc& d : graph->parameters) {
    if (!d.structural) continue;
    if (d.type == ParamType::boolean) (void)params.set(d.name, !params.get_bool(d.name));
    if (d.type == ParamType::integer && d.has_range()) (void)params.set(d.name, static_cast<int>(d.max));
    if (d.type == ParamType::enumeration && !d.options.empty()) (void)params.set(d.name, d.options.back());
  }
  (void)compile(*graph, registry(), params, {7, 3, 16}, {.no_reuse = size % 2 == 1, .extended_lifetimes = size % 3 == 0});
  return 0;
}
