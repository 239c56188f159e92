#include "techniques/esm/silhouette/alpha_contours.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

namespace penumbra::esm {
namespace {

// One side of the mask's outline in texture texels (x = u * width, y = v * height), oriented so
// that the transparent side is on the left of a -> b: outward (-dy, dx) for direction (dx, dy).
struct ContourSegment {
  float ax = 0, ay = 0, bx = 0, by = 0;
};

// Whether a texel of alpha `texture_alpha` (0-1) of `image` is covered: factor_alpha x alpha >=
// cutoff, the reference's test ("alpha < cutoff is a hole"). Without an image (null, empty or short
// of its pixels) the factor alone decides.
struct AlphaMask {
  const scene::Image* image = nullptr;
  float factor_alpha = 1.0f;
  float cutoff = 0.5f;
  bool textured() const {
    return image && image->width > 0 && image->height > 0 &&
           image->pixels.size() >= static_cast<size_t>(image->width) * static_cast<size_t>(image->height) * 4;
  }
  bool covers(float texture_alpha) const { return !(factor_alpha * texture_alpha < cutoff); }
};

struct Point {
  float x, y;
};

// A crossing of the contour: the lattice edge between texel (x, y) and its right (horizontal,
// h = 0) or lower (h = 1) neighbour, at the midpoint of their centres.
struct Crossing {
  long x, y;
  int h;
  Point point() const {
    return h == 0 ? Point{static_cast<float>(x) + 1.0f, static_cast<float>(y) + 0.5f}
                  : Point{static_cast<float>(x) + 0.5f, static_cast<float>(y) + 1.0f};
  }
  // Unique within a region whose corner is (x0, y0) and whose rows are `stride` texels long.
  uint64_t key(long x0, long y0, long stride) const {
    return (static_cast<uint64_t>(y - y0) * static_cast<uint64_t>(stride) + static_cast<uint64_t>(x - x0)) * 2 +
           static_cast<uint64_t>(h);
  }
};

float distance_to_line(Point p, Point a, Point b) {
  const float dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
  if (len < 1e-12f) return std::hypot(p.x - a.x, p.y - a.y);
  return std::abs((p.x - a.x) * dy - (p.y - a.y) * dx) / len;
}

// Douglas-Peucker: keeps the points of `chain` [first, last] further than the tolerance from
// the line of the kept ones.
void thin(const std::vector<Point>& chain, size_t first, size_t last, std::vector<char>& keep) {
  if (last <= first + 1) return;
  float worst = -1.0f;
  size_t at = first;
  for (size_t i = first + 1; i < last; ++i)
    if (const float d = distance_to_line(chain[i], chain[first], chain[last]); d > worst) worst = d, at = i;
  if (worst <= kContourTolerance) return;
  keep[at] = 1;
  thin(chain, first, at, keep);
  thin(chain, at, last, keep);
}

void emit_thinned(const std::vector<Point>& chain, std::vector<ContourSegment>& out) {
  if (chain.size() < 2) return;
  std::vector<char> keep(chain.size(), 0);
  keep.front() = keep.back() = 1;
  if (chain.size() > 3 && chain.front().x == chain.back().x && chain.front().y == chain.back().y) {
    // A closed loop: split it at its point furthest from the start, so both halves have ends.
    size_t far = 0;
    float best = -1.0f;
    for (size_t i = 1; i + 1 < chain.size(); ++i)
      if (const float d = std::hypot(chain[i].x - chain[0].x, chain[i].y - chain[0].y); d > best) best = d, far = i;
    keep[far] = 1;
    thin(chain, 0, far, keep);
    thin(chain, far, chain.size() - 1, keep);
  } else {
    thin(chain, 0, chain.size() - 1, keep);
  }
  Point previous = chain.front();
  for (size_t i = 1; i < chain.size(); ++i) {
    if (!keep[i]) continue;
    out.push_back({previous.x, previous.y, chain[i].x, chain[i].y});
    previous = chain[i];
  }
}

// Segment a-b clipped to triangle t (texel space); false when nothing is left.
bool clip_to_triangle(const glm::vec2 t[3], glm::vec2& a, glm::vec2& b) {
  const float area = (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x);
  const float side = area > 0.0f ? 1.0f : -1.0f;
  float enter = 0.0f, leave = 1.0f;
  for (int k = 0; k < 3; ++k) {
    const glm::vec2 e0 = t[k], e1 = t[(k + 1) % 3];
    auto inside = [&](glm::vec2 p) { return side * ((e1.x - e0.x) * (p.y - e0.y) - (e1.y - e0.y) * (p.x - e0.x)); };
    const float fa = inside(a), fb = inside(b);
    if (fa < 0.0f && fb < 0.0f) return false;
    if (fa < 0.0f) enter = std::max(enter, fa / (fa - fb));
    if (fb < 0.0f) leave = std::min(leave, fa / (fa - fb));
  }
  if (enter >= leave) return false;
  const glm::vec2 d = b - a;
  b = a + leave * d;
  a = a + enter * d;
  return true;
}

// The mask's contour over the texel cells whose centres span [x0, x1] x [y0, y1] (texel indices,
// repeat wrap), thinned, appended to `out`; nothing for a region of more than 4 x kMaxContourCells.
void trace_alpha_contour(const AlphaMask& mask, long x0, long y0, long x1, long y1, std::vector<ContourSegment>& out) {
  if (x1 <= x0 || y1 <= y0 ||
      static_cast<double>(x1 - x0 + 1) * static_cast<double>(y1 - y0 + 1) > 4.0 * static_cast<double>(kMaxContourCells))
    return;
  const long w = x1 - x0 + 1;
  std::vector<char> cov(static_cast<size_t>(w) * static_cast<size_t>(y1 - y0 + 1));
  if (mask.textured()) {  // the mask row by row, the wrapped columns found once
    const long iw = mask.image->width, ih = mask.image->height;
    std::vector<size_t> column(static_cast<size_t>(w));
    for (long x = x0; x <= x1; ++x) column[static_cast<size_t>(x - x0)] = static_cast<size_t>(((x % iw) + iw) % iw);
    for (long y = y0; y <= y1; ++y) {
      const uint8_t* row = &mask.image->pixels[static_cast<size_t>(((y % ih) + ih) % ih) * static_cast<size_t>(iw) * 4];
      char* out_row = &cov[static_cast<size_t>((y - y0) * w)];
      for (long x = 0; x < w; ++x) out_row[x] = mask.covers(row[column[static_cast<size_t>(x)] * 4 + 3] / 255.0f);
    }
  } else {
    std::fill(cov.begin(), cov.end(), mask.covers(1.0f));
  }
  auto at = [&](long x, long y) { return cov[static_cast<size_t>((y - y0) * w + (x - x0))] != 0; };
  // Marching squares over the cells between texel centres. Walking a cell's corners k0 (x, y),
  // k1 (x+1, y), k2 (x+1, y+1), k3 (x, y+1), the crossing on side k enters the mask when k is
  // uncovered and k+1 covered; each entering crossing joins the next crossing along the walk,
  // which leaves it. Covered corners of a saddle cell stay apart (diagonal texels do not connect).
  std::vector<std::pair<Crossing, Crossing>> pieces;
  for (long y = y0; y < y1; ++y)
    for (long x = x0; x < x1; ++x) {
      const bool c[4] = {at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y + 1)};
      if (c[0] == c[1] && c[1] == c[2] && c[2] == c[3]) continue;
      const Crossing side[4] = {{x, y, 0}, {x + 1, y, 1}, {x, y + 1, 0}, {x, y, 1}};
      for (int k = 0; k < 4; ++k) {
        if (c[k] || !c[(k + 1) % 4]) continue;  // not entering
        for (int n = 1; n < 4; ++n) {
          const int j = (k + n) % 4;
          if (c[j] != c[(j + 1) % 4]) {
            pieces.push_back({side[k], side[j]});
            break;
          }
        }
      }
    }
  // Join the pieces into chains: a crossing inside the region ends one piece and starts the next.
  std::unordered_map<uint64_t, uint32_t> starting;
  starting.reserve(pieces.size());
  for (size_t i = 0; i < pieces.size(); ++i) starting.emplace(pieces[i].first.key(x0, y0, w), static_cast<uint32_t>(i));
  constexpr uint32_t kNone = UINT32_MAX;
  std::vector<uint32_t> next(pieces.size(), kNone);
  std::vector<char> entered(pieces.size(), 0);  // some piece leads into it
  for (size_t i = 0; i < pieces.size(); ++i)
    if (auto it = starting.find(pieces[i].second.key(x0, y0, w)); it != starting.end()) {
      next[i] = it->second;
      entered[it->second] = 1;
    }
  std::vector<char> used(pieces.size(), 0);
  std::vector<Point> chain;
  auto walk = [&](size_t i) {
    chain.clear();
    chain.push_back(pieces[i].first.point());
    for (uint32_t k = static_cast<uint32_t>(i); k != kNone && !used[k]; k = next[k]) {
      used[k] = 1;
      chain.push_back(pieces[k].second.point());
    }
    emit_thinned(chain, out);
  };
  for (size_t i = 0; i < pieces.size(); ++i)  // open chains first, from their starts
    if (!used[i] && !entered[i]) walk(i);
  for (size_t i = 0; i < pieces.size(); ++i)  // then the closed loops
    if (!used[i]) walk(i);
}

}  // namespace

Result<SilhouetteGeometry> build_alpha_contour_quads(const scene::Mesh& mesh, const scene::Material& material,
                                                     const scene::Image* image, const SilhouetteOptions& options) {
  const AlphaMask mask{image, material.base_color_factor.a, material.alpha_cutoff};
  if (!mask.textured()) {
    if (mask.covers(1.0f)) return build_silhouette_quads(mesh, options);
    return SilhouetteGeometry{};
  }
  SilhouetteGeometry out;
  SilhouetteStats& st = out.stats;
  const glm::vec2 texels(static_cast<float>(image->width), static_cast<float>(image->height));
  std::vector<ContourSegment> contour;
  size_t traced_cells = 0;
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const uint32_t* idx = &mesh.indices[3 * t];
    if (idx[0] >= mesh.vertices.size() || idx[1] >= mesh.vertices.size() || idx[2] >= mesh.vertices.size()) {
      ++st.degenerate_triangles;
      continue;
    }
    const scene::Vertex* v[3] = {&mesh.vertices[idx[0]], &mesh.vertices[idx[1]], &mesh.vertices[idx[2]]};
    const glm::vec3 edge1 = v[1]->position - v[0]->position, edge2 = v[2]->position - v[0]->position;
    const glm::vec3 cross = glm::cross(edge1, edge2);
    const glm::vec2 tx[3] = {v[0]->uv * texels, v[1]->uv * texels, v[2]->uv * texels};
    const glm::vec2 du1 = tx[1] - tx[0], du2 = tx[2] - tx[0];
    const float uv_area = du1.x * du2.y - du1.y * du2.x;
    const float len = glm::length(cross);
    if (!(len > 0.0f) || !std::isfinite(len) || !(std::abs(uv_area) > 1e-8f) || !std::isfinite(uv_area)) {
      ++st.degenerate_triangles;
      continue;
    }
    ++st.facets;
    const glm::vec2 lo = glm::min(tx[0], glm::min(tx[1], tx[2])), hi = glm::max(tx[0], glm::max(tx[1], tx[2]));
    const long x0 = static_cast<long>(std::floor(lo.x)) - 1, x1 = static_cast<long>(std::floor(hi.x)) + 1;
    const long y0 = static_cast<long>(std::floor(lo.y)) - 1, y1 = static_cast<long>(std::floor(hi.y)) + 1;
    const double cells = static_cast<double>(x1 - x0) * static_cast<double>(y1 - y0);
    if (cells > static_cast<double>(kMaxContourCells) ||
        static_cast<double>(traced_cells) + cells > static_cast<double>(options.max_contour_cells)) {
      ++st.alpha_skipped;
      continue;
    }
    traced_cells += static_cast<size_t>(cells);
    contour.clear();
    trace_alpha_contour(mask, x0, y0, x1, y1, contour);
    // Texture texels -> object space: affine over the triangle (its barycentric coordinates).
    const glm::mat2 to_bary = glm::inverse(glm::mat2(du1, du2));
    const glm::vec3 normal = cross / len;
    auto object = [&](glm::vec2 p) {
      const glm::vec2 l = to_bary * (p - tx[0]);
      return v[0]->position + l.x * edge1 + l.y * edge2;
    };
    for (const ContourSegment& s : contour) {
      glm::vec2 a(s.ax, s.ay), b(s.bx, s.by);
      if (!clip_to_triangle(tx, a, b) || glm::length(b - a) < 1e-4f) continue;
      const glm::vec2 d = b - a, away_uv(-d.y, d.x);
      const glm::vec3 pa = object(a), pb = object(b);
      const glm::vec2 l = to_bary * away_uv;
      glm::vec3 away = l.x * edge1 + l.y * edge2;
      const glm::vec3 along = pb - pa;
      const float along2 = glm::dot(along, along);
      if (!(along2 > 0.0f)) continue;
      away -= along * (glm::dot(away, along) / along2);  // in the plane, across the contour
      if (!(glm::length(away) > 0.0f)) continue;
      if (++st.alpha_contours > options.max_edges) {
        Error err = make_error("mesh '" + mesh.name + "' has more than " + std::to_string(options.max_edges) +
                               " alpha-mask contour pieces; extended shadow maps take at most " +
                               std::to_string(options.max_edges) +
                               " edges per mesh: split the mesh, use a smaller mask texture or another technique");
        err.where = "mesh '" + mesh.name + "'";
        return err;
      }
      add_sheet_boundary(out.quads, pa, pb, normal, away);
    }
  }
  st.edges = st.alpha_contours;
  st.quads = out.quad_count();
  return out;
}

}  // namespace penumbra::esm
