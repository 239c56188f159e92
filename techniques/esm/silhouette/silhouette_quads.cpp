#include "techniques/esm/silhouette/silhouette_quads.h"

#include <algorithm>
#include <cmath>

#include "techniques/esm/silhouette/alpha_contours.h"
#include "techniques/esm/silhouette/edge_adjacency.h"

namespace penumbra::esm {
namespace {

// Normals closer than this are one plane (cos of ~0.08 degrees).
constexpr float kCoplanarCos = 0.999999f;

glm::vec4 plane_through(const glm::vec3& n, const glm::vec3& p) { return glm::vec4(n, -glm::dot(n, p)); }

glm::vec3 normalized_or(const glm::vec3& v, const glm::vec3& fallback) {
  const float len = glm::length(v);
  return len > 1e-6f ? v / len : fallback;
}

// Facet normals n1, n2 meeting at more than 90 degrees (or folded flat, 180): two quads with
// the bevel plane between them (Figure 5). `bevel` is the bevel plane's unit normal.
void add_beveled(std::vector<SilhouetteQuad>& quads, const glm::vec3& a, const glm::vec3& b, const glm::vec3& n1,
                 const glm::vec3& n2, const glm::vec3& bevel) {
  const glm::vec4 p1 = plane_through(n1, a), p2 = plane_through(n2, a), pb = plane_through(bevel, a);
  quads.push_back({a, b, p1, pb, normalized_or(n1 + bevel, bevel)});
  quads.push_back({a, b, pb, p2, normalized_or(bevel + n2, bevel)});
}

class QuadWriter {
 public:
  explicit QuadWriter(SilhouetteGeometry& out) : out_(out) {}

  // One degenerate quad between planes p and q along edge a-b, extruded along `extrusion`.
  void quad(const glm::vec3& a, const glm::vec3& b, const glm::vec4& p, const glm::vec4& q, const glm::vec3& extrusion) {
    out_.quads.push_back({a, b, p, q, extrusion});
  }

  void beveled(const glm::vec3& a, const glm::vec3& b, const glm::vec3& n1, const glm::vec3& n2, const glm::vec3& bevel) {
    add_beveled(out_.quads, a, b, n1, n2, bevel);
  }

  // The boundary of facet `f` along its side `side`, away from the facet.
  void open_side(const EdgeAdjacency& adj, const Facet& f, int side) {
    const glm::vec3& a = adj.positions[f.v[side]];
    const glm::vec3& b = adj.positions[f.v[(side + 1) % 3]];
    glm::vec3 outward = glm::cross(b - a, f.normal);
    if (glm::dot(outward, adj.opposite(f, side) - a) > 0.0f) outward = -outward;
    add_sheet_boundary(out_.quads, a, b, f.normal, outward);
  }

 private:
  SilhouetteGeometry& out_;
};

}  // namespace

void add_sheet_boundary(std::vector<SilhouetteQuad>& quads, const glm::vec3& a, const glm::vec3& b,
                        const glm::vec3& normal, const glm::vec3& away) {
  add_beveled(quads, a, b, normal, -normal, normalized_or(away, normal));
}

// A closed mesh whose facets enclose a negative volume is wound inside out: every facet is
// turned so its normal points out of the volume (the divergence theorem's sign).
bool turn_outwards(EdgeAdjacency& adj) {
  for (const Edge& e : adj.edges) {
    const EdgeUse* u = &adj.uses[e.first_use];
    if (e.use_count != 2 || u[0].forward == u[1].forward) return false;  // not closed
  }
  double volume = 0.0;
  for (const Facet& f : adj.facets)
    volume += glm::dot(glm::dvec3(adj.positions[f.v[0]]),
                       glm::cross(glm::dvec3(adj.positions[f.v[1]]), glm::dvec3(adj.positions[f.v[2]])));
  if (adj.facets.empty() || volume >= 0.0) return false;
  for (Facet& f : adj.facets) {
    std::swap(f.v[1], f.v[2]);
    f.normal = -f.normal;
    f.d = -f.d;
  }
  // Facet (v0, v2, v1)'s side 2 - k is the old side k reversed.
  for (EdgeUse& u : adj.uses) {
    u.side = static_cast<uint8_t>(2 - u.side);
    u.forward = !u.forward;
  }
  return true;
}

Result<SilhouetteGeometry> build_silhouette_quads(const scene::Mesh& mesh, const SilhouetteOptions& options) {
  EdgeAdjacency adj = build_edge_adjacency(mesh, options.weld_tolerance);
  const bool flipped = turn_outwards(adj);
  SilhouetteGeometry out;
  SilhouetteStats& st = out.stats;
  st.flipped = flipped;
  st.welded_vertices = adj.positions.size();
  st.facets = adj.facets.size();
  st.degenerate_triangles = adj.degenerate_triangles;
  st.edges = adj.edges.size();
  if (st.edges > options.max_edges) {
    Error err = make_error("mesh '" + mesh.name + "' has " + std::to_string(st.edges) + " edges (" +
                           std::to_string(st.facets) + " triangles); extended shadow maps take at most " +
                           std::to_string(options.max_edges) +
                           " edges per mesh: split the mesh or use another technique");
    err.where = "mesh '" + mesh.name + "'";
    return err;
  }
  QuadWriter writer(out);
  for (const Edge& e : adj.edges) {
    const EdgeUse* uses = &adj.uses[e.first_use];
    const bool manifold = e.use_count == 2 && uses[0].forward != uses[1].forward;
    if (!manifold) {  // open, non-manifold or inconsistently wound: each side on its own
      if (e.use_count == 1) ++st.open;
      else if (e.use_count == 2) ++st.inconsistent;
      else ++st.non_manifold;
      for (uint32_t k = 0; k < e.use_count; ++k) writer.open_side(adj, adj.facets[uses[k].facet], uses[k].side);
      continue;
    }
    const Facet& f1 = adj.facets[uses[0].facet];
    const Facet& f2 = adj.facets[uses[1].facet];
    const glm::vec3 &n1 = f1.normal, &n2 = f2.normal;
    const float cos_angle = glm::dot(n1, n2);
    if (cos_angle > kCoplanarCos) {
      ++st.coplanar;
      continue;
    }
    const glm::vec3& a = adj.positions[e.a];
    const glm::vec3& b = adj.positions[e.b];
    // Convexity: facet 2's far corner behind facet 1's plane (and vice versa), measured against
    // the edge length so the test means the same at every scale.
    const float scale = glm::length(b - a);
    const float front1 = glm::dot(n1, adj.opposite(f2, uses[1].side) - a);
    const float front2 = glm::dot(n2, adj.opposite(f1, uses[0].side) - a);
    if (front1 > 1e-6f * scale && front2 > 1e-6f * scale) {
      ++st.concave;
      continue;
    }
    ++st.convex;
    if (cos_angle >= 0.0f) {
      writer.quad(a, b, plane_through(n1, a), plane_through(n2, a), normalized_or(n1 + n2, n1));
      continue;
    }
    ++st.beveled;
    // Folded flat (n2 = -n1, a zero-thickness sheet): the bevel is the in-plane direction away
    // from the facets.
    glm::vec3 flat = glm::cross(b - a, n1);
    if (glm::dot(flat, adj.opposite(f1, uses[0].side) - a) > 0.0f) flat = -flat;
    writer.beveled(a, b, n1, n2, normalized_or(n1 + n2, normalized_or(flat, n1)));
  }
  st.quads = out.quad_count();
  return out;
}

Result<std::vector<SilhouetteGeometry>> build_scene_silhouettes(const scene::Scene& scene,
                                                                const SilhouetteOptions& options) {
  std::vector<SilhouetteGeometry> out(scene.meshes.size());
  for (uint32_t i = 0; i < scene.meshes.size(); ++i) {
    const scene::Mesh& mesh = scene.meshes[i];
    const scene::Material* material = mesh.material < scene.materials.size() ? &scene.materials[mesh.material] : nullptr;
    Result<SilhouetteGeometry> g = [&]() -> Result<SilhouetteGeometry> {
      if (!material || material->alpha_mode != scene::AlphaMode::mask) return build_silhouette_quads(mesh, options);
      if (!options.alpha_contours) return SilhouetteGeometry{};
      const int texture = material->base_color_texture;
      const scene::Image* image =
          texture >= 0 && static_cast<size_t>(texture) < scene.images.size() ? &scene.images[static_cast<size_t>(texture)] : nullptr;
      return build_alpha_contour_quads(mesh, *material, image, options);
    }();
    if (!g) {
      Error e = g.error();
      e.where = "scene mesh " + std::to_string(i) + " '" + scene.meshes[i].name + "'";
      return e;
    }
    out[i] = std::move(*g);
  }
  return out;
}

}  // namespace penumbra::esm
