#pragma once
// What the graph view shows, GL-free: the compiled plan's passes as nodes (those that run, in
// execution order, with their time, the slowest marked; culled and disabled ones with why),
// resources as edges from the pass that writes a version to each pass that reads it (imported
// and last-frame resources come from a "frame inputs" node, the outputs go to "frame output"),
// a dot layout of it all, and the physical textures' lifetimes for the timeline.
//
//   GraphViewModel m = build_graph_view(session.plan(), session.graph(), times_ms);
//   Result<GraphLayout> l = layout_with_dot(m.input);
#include <string>
#include <vector>

#include "sandbox/graph_layout.h"
#include "graph/graph_desc.h"
#include "graph/plan.h"

namespace penumbra::sandbox {

struct GraphViewModel {
  enum class State { runs, culled, disabled, io };
  struct Pass {
    std::string name, type;
    State state = State::runs;
    std::string why;                   // culled / disabled: the reason (disabled: its `enabled`)
    double ms = 0.0;                   // last time (runs only)
    bool slowest = false;
    std::vector<std::string> outputs;  // resources it writes (click: view the first)
  };
  std::vector<Pass> nodes;             // LayoutInput order: passes that run, culled, disabled, io
  LayoutInput input;
  double total_ms = 0.0;
  // One bar of the timeline: a resource version held by a physical texture over [first, last]
  // (pass indices; last == passes.size(): to the end of the frame).
  struct Lifetime {
    int physical = 0;
    std::string label;  // "shadow_map@1"
    int first = 0, last = 0;
  };
  std::vector<Lifetime> lifetimes;
  int physical_count = 0;
};

GraphViewModel build_graph_view(const graph::CompiledPlan& plan, const graph::GraphDesc& graph,
                                const std::vector<double>& pass_ms);

// The model and its layout as JSON (the scripts' `graph` step): {"passes": [{"name", "type",
// "state", "why", "ms", "slowest", "x", "y"}], "edges": [{"from", "to", "label"}], "total_ms",
// "lifetimes": [...]}.
std::string graph_view_json(const GraphViewModel& model, const GraphLayout* layout);

}  // namespace penumbra::sandbox
