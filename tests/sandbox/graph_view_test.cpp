// The graph view's model and its Graphviz dot layout on a plan built here: every pass is a
// node, culled and disabled ones say why, resources are edges from writer to reader, the
// slowest pass is marked, and dot places nodes apart with each edge running forwards.
#include <gtest/gtest.h>

#include <algorithm>

#include "sandbox/graph_layout.h"
#include "sandbox/graph_view_model.h"

namespace penumbra::sandbox {
namespace {

graph::PlannedPass pass(const std::string& name, std::vector<graph::PlannedBinding> bindings) {
  graph::PlannedPass p{.type = name + "_type", .name = name, .declared_as = name};
  p.bindings = std::move(bindings);
  return p;
}

graph::PlannedBinding reads(const std::string& r, int v) {
  return {.slot = "in", .access = graph::Access::read, .resource = r, .read_version = v};
}
graph::PlannedBinding writes(const std::string& r, int v) {
  return {.slot = "out", .access = graph::Access::write, .resource = r, .write_version = v};
}

// gbuffer -> shadow_map -> filter -> lighting, lighting also reads the G-buffer; blur disabled.
graph::CompiledPlan plan() {
  graph::CompiledPlan p;
  p.passes = {pass("gbuffer", {writes("gbuffer_position", 1)}),
              pass("shadow_map", {writes("depth", 1)}),
              pass("filter_with_a_rather_long_pass_name", {reads("depth", 1), reads("gbuffer_position", 1), writes("mask", 1)}),
              pass("lighting", {reads("mask", 1), reads("gbuffer_position", 1), reads("environment", 0), writes("color", 1)})};
  p.versions = {{"gbuffer_position", 1, graph::ResourceKind::texture, 0, 0, 0, 3},
                {"depth", 1, graph::ResourceKind::texture, 1, 1, 1, 2},
                {"mask", 1, graph::ResourceKind::texture, 1, 2, 2, 3},
                {"color", 1, graph::ResourceKind::texture, 2, 3, 3, 4}};
  p.physical.resize(3);
  p.disabled = {"blur"};
  p.culled = {"debug_view"};
  p.outputs = {"color"};
  return p;
}

TEST(GraphView, EveryPassIsANodeAndResourcesAreEdgesFromWriterToReader) {
  graph::GraphDesc g;
  g.passes.push_back({.type = "blur", .name = "blur", .enabled = "$use_blur"});
  const GraphViewModel m = build_graph_view(plan(), g, {0.1, 0.9, 0.4, 0.2});
  std::vector<std::string> names;
  for (const auto& n : m.nodes) names.push_back(n.name);
  EXPECT_EQ(names, (std::vector<std::string>{"gbuffer", "shadow_map", "filter_with_a_rather_long_pass_name", "lighting",
                                             "debug_view", "blur", "frame inputs", "frame output"}));
  EXPECT_TRUE(m.nodes[1].slowest);
  EXPECT_EQ(std::count_if(m.nodes.begin(), m.nodes.end(), [](const auto& n) { return n.slowest; }), 1);
  EXPECT_NEAR(m.total_ms, 1.6, 1e-9);
  EXPECT_EQ(m.nodes[4].state, GraphViewModel::State::culled);
  EXPECT_EQ(m.nodes[5].state, GraphViewModel::State::disabled);
  EXPECT_NE(m.nodes[5].why.find("$use_blur"), std::string::npos);
  auto has_edge = [&](int from, int to, const std::string& label) {
    return std::any_of(m.input.edges.begin(), m.input.edges.end(),
                       [&](const LayoutInput::Edge& e) { return e.from == from && e.to == to && e.label == label; });
  };
  EXPECT_TRUE(has_edge(1, 2, "depth"));
  EXPECT_TRUE(has_edge(0, 2, "gbuffer_position"));
  EXPECT_TRUE(has_edge(0, 3, "gbuffer_position"));
  EXPECT_TRUE(has_edge(2, 3, "mask"));
  EXPECT_TRUE(has_edge(6, 3, "environment")) << "version 0 comes from outside the frame";
  EXPECT_TRUE(has_edge(3, 7, "color"));
  EXPECT_EQ(m.input.edges.size(), 6u);
  EXPECT_EQ(m.lifetimes.size(), 4u);
}

TEST(GraphView, DotPlacesNodesApartAndEdgesRunForwards) {
  const GraphViewModel m = build_graph_view(plan(), {}, {});
  Result<GraphLayout> l = layout_with_dot(m.input);
  ASSERT_TRUE(l) << l.error().to_string();
  ASSERT_EQ(l->nodes.size(), m.nodes.size());
  ASSERT_EQ(l->edges.size(), m.input.edges.size());
  for (size_t i = 0; i < l->nodes.size(); ++i) {
    EXPECT_NEAR(l->nodes[i].size.x, m.input.nodes[i].width, 1.0f) << "fixed size: long names keep their width";
    for (size_t j = i + 1; j < l->nodes.size(); ++j) {
      const glm::vec2 d = glm::abs(l->nodes[i].center - l->nodes[j].center);
      const glm::vec2 reach = 0.5f * (l->nodes[i].size + l->nodes[j].size);
      EXPECT_TRUE(d.x >= reach.x || d.y >= reach.y) << m.nodes[i].name << " overlaps " << m.nodes[j].name;
    }
  }
  for (size_t k = 0; k < l->edges.size(); ++k) {
    const LayoutInput::Edge& e = m.input.edges[k];
    EXPECT_LT(l->nodes[size_t(e.from)].center.x, l->nodes[size_t(e.to)].center.x) << "left to right: " << e.label;
    EXPECT_EQ(l->edges[k].points.size() % 3, 1u);
  }
  EXPECT_GT(l->size.x, 0.0f);
}

}  // namespace
}  // namespace penumbra::sandbox
