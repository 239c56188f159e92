#include "techniques/esm/silhouette/edge_adjacency.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

namespace penumbra::esm {
namespace {

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Position welding on a hash grid of cell size `eps`: a position joins the first welded vertex
// within `eps` in its cell or the 26 around it (so two points straddling a cell border still
// weld), in vertex order (deterministic).
class Welder {
 public:
  explicit Welder(float eps) : eps_(eps), inv_cell_(eps > 0.0f ? 1.0f / eps : 0.0f) {}

  uint32_t weld(const glm::vec3& p, std::vector<glm::vec3>& positions) {
    const glm::ivec3 c = cell(p);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = grid_.find(key(c + glm::ivec3(dx, dy, dz)));
          if (it == grid_.end()) continue;
          for (uint32_t id : it->second)
            if (glm::all(glm::lessThanEqual(glm::abs(positions[id] - p), glm::vec3(eps_)))) return id;
        }
    const uint32_t id = static_cast<uint32_t>(positions.size());
    positions.push_back(p);
    grid_[key(c)].push_back(id);
    return id;
  }

 private:
  glm::ivec3 cell(const glm::vec3& p) const {
    if (inv_cell_ == 0.0f) return glm::ivec3(0);
    const glm::vec3 q = glm::floor(p * inv_cell_);
    // Clamp so a huge coordinate cannot overflow the int conversion.
    return glm::ivec3(glm::clamp(q, glm::vec3(-1e9f), glm::vec3(1e9f)));
  }
  static uint64_t key(const glm::ivec3& c) {
    const uint64_t x = static_cast<uint32_t>(c.x), y = static_cast<uint32_t>(c.y), z = static_cast<uint32_t>(c.z);
    return (x * 0x9E3779B97F4A7C15ull) ^ (y * 0xC2B2AE3D27D4EB4Full) ^ (z * 0x165667B19E3779F9ull);
  }
  float eps_, inv_cell_;
  std::unordered_map<uint64_t, std::vector<uint32_t>> grid_;
};

}  // namespace

EdgeAdjacency build_edge_adjacency(const scene::Mesh& mesh, float relative_tolerance) {
  EdgeAdjacency adj;
  scene::Bounds box;
  for (const scene::Vertex& v : mesh.vertices)
    if (finite(v.position)) box.extend(v.position);
  const float diagonal = box.empty() ? 0.0f : glm::length(box.extent());
  Welder welder(std::max(relative_tolerance, 0.0f) * diagonal);
  constexpr uint32_t kNoVertex = 0xFFFFFFFFu;
  adj.weld_of.assign(mesh.vertices.size(), kNoVertex);
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    if (finite(mesh.vertices[i].position)) adj.weld_of[i] = welder.weld(mesh.vertices[i].position, adj.positions);

  // Facets: skip anything that has no plane.
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    Facet f;
    bool ok = true;
    for (int k = 0; k < 3 && ok; ++k) {
      const uint32_t i = mesh.indices[t + static_cast<size_t>(k)];
      ok = i < adj.weld_of.size() && adj.weld_of[i] != kNoVertex;
      if (ok) f.v[k] = adj.weld_of[i];
    }
    ok = ok && f.v[0] != f.v[1] && f.v[1] != f.v[2] && f.v[2] != f.v[0];
    if (ok) {
      const glm::vec3 e1 = adj.positions[f.v[1]] - adj.positions[f.v[0]];
      const glm::vec3 e2 = adj.positions[f.v[2]] - adj.positions[f.v[0]];
      const glm::vec3 n = glm::cross(e1, e2);
      const float len = glm::length(n);
      // Zero area: the sine of the corner angle below 1e-7 (collinear within float precision).
      ok = std::isfinite(len) && len > 1e-7f * glm::length(e1) * glm::length(e2);
      if (ok) {
        f.normal = n / len;
        f.d = -glm::dot(f.normal, adj.positions[f.v[0]]);
      }
    }
    if (!ok) {
      ++adj.degenerate_triangles;
      continue;
    }
    adj.facets.push_back(f);
  }

  // Edge uses sorted by welded edge; runs of equal (a, b) are one edge.
  struct Record {
    uint32_t a, b;
    EdgeUse use;
  };
  std::vector<Record> records;
  records.reserve(adj.facets.size() * 3);
  for (uint32_t fi = 0; fi < adj.facets.size(); ++fi)
    for (uint8_t k = 0; k < 3; ++k) {
      const uint32_t from = adj.facets[fi].v[k], to = adj.facets[fi].v[(k + 1) % 3];
      records.push_back({std::min(from, to), std::max(from, to), {fi, k, from < to}});
    }
  std::sort(records.begin(), records.end(), [](const Record& x, const Record& y) {
    return std::tie(x.a, x.b, x.use.facet, x.use.side) < std::tie(y.a, y.b, y.use.facet, y.use.side);
  });
  adj.uses.reserve(records.size());
  for (size_t i = 0; i < records.size();) {
    Edge e{records[i].a, records[i].b, static_cast<uint32_t>(adj.uses.size()), 0};
    for (; i < records.size() && records[i].a == e.a && records[i].b == e.b; ++i, ++e.use_count)
      adj.uses.push_back(records[i].use);
    adj.edges.push_back(e);
  }
  return adj;
}

}  // namespace penumbra::esm
