#include "sandbox/graph_layout.h"

#include <graphviz/cgraph.h>
#include <graphviz/gvc.h>

#include <memory>

namespace penumbra::sandbox {

namespace {

constexpr float kPointsPerInch = 72.0f;

// cgraph takes char*, not const char*.
char* mut(const char* s) { return const_cast<char*>(s); }

struct GvcDeleter {
  void operator()(GVC_t* g) const { gvFreeContext(g); }
};

GVC_t* context() {
  // One context a process: plugins load once (gvContext reads Graphviz's plugin config).
  static std::unique_ptr<GVC_t, GvcDeleter> gvc(gvContext());
  return gvc.get();
}

}  // namespace

Result<GraphLayout> layout_with_dot(const LayoutInput& input) {
  GVC_t* gvc = context();
  if (!gvc) return make_error("graphviz: no context (libgvc plugins missing?)", ErrorKind::unavailable);
  Agraph_t* g = agopen(mut("plan"), Agdirected, nullptr);
  agattr(g, AGRAPH, mut("rankdir"), mut(input.left_to_right ? "LR" : "TB"));
  agattr(g, AGRAPH, mut("nodesep"), mut("0.25"));
  agattr(g, AGRAPH, mut("ranksep"), mut("0.45"));
  agattr(g, AGNODE, mut("shape"), mut("box"));
  agattr(g, AGNODE, mut("fixedsize"), mut("true"));
  agattr(g, AGNODE, mut("width"), mut("1"));
  agattr(g, AGNODE, mut("height"), mut("0.4"));
  agattr(g, AGNODE, mut("label"), mut(""));
  agattr(g, AGEDGE, mut("label"), mut(""));
  std::vector<Agnode_t*> nodes;
  for (size_t i = 0; i < input.nodes.size(); ++i) {
    Agnode_t* n = agnode(g, mut(("n" + std::to_string(i)).c_str()), 1);
    agset(n, mut("width"), mut(std::to_string(input.nodes[i].width / kPointsPerInch).c_str()));
    agset(n, mut("height"), mut(std::to_string(input.nodes[i].height / kPointsPerInch).c_str()));
    nodes.push_back(n);
  }
  std::vector<Agedge_t*> edges;
  for (size_t i = 0; i < input.edges.size(); ++i) {
    const LayoutInput::Edge& e = input.edges[i];
    if (e.from < 0 || e.to < 0 || size_t(e.from) >= nodes.size() || size_t(e.to) >= nodes.size()) {
      agclose(g);
      return make_error("graph layout: edge " + std::to_string(i) + " names a node that does not exist",
                        ErrorKind::internal);
    }
    Agedge_t* edge = agedge(g, nodes[e.from], nodes[e.to], mut(("e" + std::to_string(i)).c_str()), 1);
    agset(edge, mut("label"), mut(e.label.c_str()));
    edges.push_back(edge);
  }
  if (gvLayout(gvc, g, "dot") != 0) {
    agclose(g);
    return make_error("graphviz: the dot layout failed", ErrorKind::internal);
  }
  GraphLayout out;
  const boxf bb = GD_bb(g);
  const float top = static_cast<float>(bb.UR.y);
  auto flip = [&](pointf p) { return glm::vec2(static_cast<float>(p.x - bb.LL.x), top - static_cast<float>(p.y)); };
  out.size = {static_cast<float>(bb.UR.x - bb.LL.x), static_cast<float>(bb.UR.y - bb.LL.y)};
  for (Agnode_t* n : nodes)
    out.nodes.push_back({flip(ND_coord(n)), glm::vec2(static_cast<float>(ND_width(n)), static_cast<float>(ND_height(n))) *
                                                kPointsPerInch});
  for (Agedge_t* e : edges) {
    GraphLayout::Edge le;
    if (const splines* s = ED_spl(e); s && s->size > 0) {
      const bezier& b = s->list[0];
      for (int k = 0; k < b.size; ++k) le.points.push_back(flip(b.list[k]));
      le.head = b.eflag ? flip(b.ep) : (le.points.empty() ? glm::vec2(0.0f) : le.points.back());
    }
    if (const textlabel_t* l = ED_label(e)) le.label_at = flip(l->pos);
    else if (!le.points.empty()) le.label_at = le.points[le.points.size() / 2];
    out.edges.push_back(std::move(le));
  }
  gvFreeLayout(gvc, g);
  agclose(g);
  return out;
}

}  // namespace penumbra::sandbox
