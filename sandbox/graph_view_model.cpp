#include "sandbox/graph_view_model.h"

#include <algorithm>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

namespace penumbra::sandbox {

namespace {

float label_width(const std::string& text) { return std::max(96.0f, 7.0f * static_cast<float>(text.size()) + 20.0f); }

const char* state_name(GraphViewModel::State s) {
  switch (s) {
    case GraphViewModel::State::runs: return "runs";
    case GraphViewModel::State::culled: return "culled";
    case GraphViewModel::State::disabled: return "disabled";
    case GraphViewModel::State::io: return "io";
  }
  return "?";
}

}  // namespace

GraphViewModel build_graph_view(const graph::CompiledPlan& plan, const graph::GraphDesc& graph,
                                const std::vector<double>& pass_ms) {
  GraphViewModel m;
  auto add = [&](GraphViewModel::Pass p) {
    m.input.nodes.push_back({p.name, label_width(p.name), p.state == GraphViewModel::State::io ? 24.0f : 34.0f});
    m.nodes.push_back(std::move(p));
    return static_cast<int>(m.nodes.size()) - 1;
  };
  int slowest = -1;
  for (size_t i = 0; i < plan.passes.size(); ++i) {
    GraphViewModel::Pass p{.name = plan.passes[i].name, .type = plan.passes[i].type};
    p.ms = i < pass_ms.size() ? pass_ms[i] : 0.0;
    m.total_ms += p.ms;
    for (const graph::PlannedBinding& b : plan.passes[i].bindings)
      if (b.write_version >= 0) p.outputs.push_back(b.resource);
    if (slowest < 0 || p.ms > m.nodes[size_t(slowest)].ms) slowest = static_cast<int>(i);
    add(std::move(p));
  }
  if (slowest >= 0 && m.nodes[size_t(slowest)].ms > 0.0) m.nodes[size_t(slowest)].slowest = true;
  auto enabled_of = [&](const std::string& name) {
    for (const graph::PassDecl& d : graph.passes)
      if (d.name == name) return d.enabled;
    return std::string();
  };
  for (const std::string& n : plan.culled)
    add({.name = n, .state = GraphViewModel::State::culled, .why = "culled: none of its outputs reaches the frame"});
  for (const std::string& n : plan.disabled)
    add({.name = n, .state = GraphViewModel::State::disabled, .why = "disabled: enabled is " + enabled_of(n)});
  const int inputs = add({.name = "frame inputs", .state = GraphViewModel::State::io});
  const int output = add({.name = "frame output", .state = GraphViewModel::State::io});

  // Edges: producer of the version read -> reader, once per (from, to, label).
  std::map<std::pair<std::string, int>, int> producer;
  for (const graph::ResourceVersion& v : plan.versions) producer[{v.name, v.version}] = v.producer;
  std::set<std::tuple<int, int, std::string>> seen;
  auto edge = [&](int from, int to, const std::string& label) {
    if (seen.insert({from, to, label}).second) m.input.edges.push_back({from, to, label});
  };
  bool inputs_used = false;
  for (size_t i = 0; i < plan.passes.size(); ++i)
    for (const graph::PlannedBinding& b : plan.passes[i].bindings) {
      if (b.read_version < 0) continue;
      auto it = producer.find({b.resource, b.read_version});
      const int from = it != producer.end() && it->second >= 0 ? it->second : inputs;
      inputs_used = inputs_used || from == inputs;
      edge(from, static_cast<int>(i), b.resource);
    }
  for (const std::string& out : plan.outputs) {
    int last = -1, version = -1;
    for (const graph::ResourceVersion& v : plan.versions)
      if (v.name == out && v.version > version) {
        version = v.version;
        last = v.producer;
      }
    if (last >= 0) edge(last, output, out);
  }
  (void)inputs_used;

  for (const graph::ResourceVersion& v : plan.versions)
    if (v.physical >= 0) m.lifetimes.push_back({v.physical, v.label(), v.first_use, v.last_use});
  std::sort(m.lifetimes.begin(), m.lifetimes.end(),
            [](const auto& a, const auto& b) { return a.physical != b.physical ? a.physical < b.physical : a.first < b.first; });
  m.physical_count = static_cast<int>(plan.physical.size());
  return m;
}

std::string graph_view_json(const GraphViewModel& m, const GraphLayout* layout) {
  nlohmann::json j;
  j["passes"] = nlohmann::json::array();
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    const GraphViewModel::Pass& p = m.nodes[i];
    nlohmann::json n = {{"name", p.name}, {"type", p.type}, {"state", state_name(p.state)}, {"why", p.why},
                        {"ms", p.ms}, {"slowest", p.slowest}, {"outputs", p.outputs}};
    if (layout && i < layout->nodes.size()) {
      n["x"] = layout->nodes[i].center.x;
      n["y"] = layout->nodes[i].center.y;
      n["w"] = layout->nodes[i].size.x;
      n["h"] = layout->nodes[i].size.y;
    }
    j["passes"].push_back(n);
  }
  j["edges"] = nlohmann::json::array();
  for (const LayoutInput::Edge& e : m.input.edges)
    j["edges"].push_back({{"from", m.nodes[size_t(e.from)].name}, {"to", m.nodes[size_t(e.to)].name}, {"label", e.label}});
  j["total_ms"] = m.total_ms;
  j["lifetimes"] = nlohmann::json::array();
  for (const auto& l : m.lifetimes)
    j["lifetimes"].push_back({{"physical", l.physical}, {"label", l.label}, {"first", l.first}, {"last", l.last}});
  return j.dump(2) + "\n";
}

}  // namespace penumbra::sandbox
