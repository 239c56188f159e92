#pragma once
// Lays a directed graph out with Graphviz's `dot` (libgvc, Debian's libgraphviz-dev): node
// centres and sizes, and each edge as cubic Bezier control points, in points with y down (the
// way ImGui draws). GL-free; the sandbox's graph view draws the result with ImGui.
//
//   LayoutInput in;
//   in.nodes = {{"gbuffer", 90, 28}, {"shadow_map", 110, 28}};
//   in.edges = {{0, 1, "depth@1"}};
//   Result<GraphLayout> l = layout_with_dot(in);
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "util/error.h"

namespace penumbra::sandbox {

struct LayoutInput {
  struct Node {
    std::string name;
    float width = 80.0f, height = 28.0f;  // points
  };
  struct Edge {
    int from = 0, to = 0;
    std::string label;
  };
  std::vector<Node> nodes;
  std::vector<Edge> edges;
  bool left_to_right = true;  // rankdir LR (passes in execution order read left to right)
};

struct GraphLayout {
  struct Node {
    glm::vec2 center{0.0f}, size{0.0f};
  };
  struct Edge {
    std::vector<glm::vec2> points;  // 1 + 3k Bezier control points, from the tail to the head
    glm::vec2 head{0.0f};           // the arrow's tip (at the head node's border)
    glm::vec2 label_at{0.0f};
  };
  std::vector<Node> nodes;  // in LayoutInput order
  std::vector<Edge> edges;
  glm::vec2 size{0.0f};     // the bounding box
};

Result<GraphLayout> layout_with_dot(const LayoutInput& input);

}  // namespace penumbra::sandbox
