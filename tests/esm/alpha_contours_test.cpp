// The quads of alpha-masked casters (techniques/esm/silhouette/alpha_contours.h): the mask's
// contour traced in the texture, thinned, clipped to each triangle and mapped to object space.
// No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <tuple>

#include "scene/mesh_builder.h"
#include "techniques/esm/silhouette/alpha_contours.h"

using namespace penumbra;

namespace {

// A size x size RGBA8 image whose alpha is 255 where `covered(x, y)`, else 0.
scene::Image mask_image(int size, const std::function<bool(int, int)>& covered) {
  scene::Image img;
  img.name = "mask";
  img.width = img.height = size;
  img.pixels.assign(static_cast<size_t>(size) * size * 4, 200);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) img.pixels[(static_cast<size_t>(y) * size + x) * 4 + 3] = covered(x, y) ? 255 : 0;
  return img;
}

// The unit square in the z = 0 plane, two triangles, position (u_scale * u, v) for uv (u, v)
// with u from u0 to u1 (u1 < u0 mirrors the texture).
scene::Mesh sheet(float u0 = 0.0f, float u1 = 1.0f) {
  scene::Mesh m;
  m.name = "sheet";
  m.vertices = {{{0, 0, 0}, {0, 0, 1}, {u0, 0}},
                {{1, 0, 0}, {0, 0, 1}, {u1, 0}},
                {{1, 1, 0}, {0, 0, 1}, {u1, 1}},
                {{0, 1, 0}, {0, 0, 1}, {u0, 1}}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

const scene::Material kMask{.name = "leaf", .alpha_mode = scene::AlphaMode::mask, .alpha_cutoff = 0.5f};

// Each contour piece is a sheet boundary: two quads on the same a-b whose extrusions sum to the
// direction away from the covered side (add_sheet_boundary).
struct Piece {
  glm::vec3 a, b, away;
};
std::vector<Piece> pieces(const esm::SilhouetteGeometry& g) {
  std::vector<Piece> out;
  EXPECT_EQ(g.quads.size() % 2, 0u);
  for (size_t i = 0; i + 1 < g.quads.size(); i += 2) {
    EXPECT_EQ(g.quads[i].a, g.quads[i + 1].a);
    EXPECT_EQ(g.quads[i].b, g.quads[i + 1].b);
    out.push_back({g.quads[i].a, g.quads[i].b, glm::normalize(g.quads[i].extrusion + g.quads[i + 1].extrusion)});
  }
  return out;
}

double total_length(const std::vector<Piece>& ps) {
  double sum = 0.0;
  for (const Piece& p : ps) sum += glm::length(p.b - p.a);
  return sum;
}

// How many pieces end at each point: 2 everywhere on closed loops.
std::map<std::tuple<long, long, long>, int> end_counts(const std::vector<Piece>& ps) {
  std::map<std::tuple<long, long, long>, int> n;
  auto key = [](const glm::vec3& p) {
    return std::make_tuple(std::lround(p.x * 1e4), std::lround(p.y * 1e4), std::lround(p.z * 1e4));
  };
  for (const Piece& p : ps) {
    ++n[key(p.a)];
    ++n[key(p.b)];
  }
  return n;
}

// Distance of p (texels) from the boundary of the square [lo, hi]^2.
float from_square(glm::vec2 p, float lo, float hi) {
  const glm::vec2 inside = glm::clamp(p, glm::vec2(lo), glm::vec2(hi));
  if (inside != p) return glm::length(p - inside);
  return std::min({p.x - lo, hi - p.x, p.y - lo, hi - p.y});
}

}  // namespace

// Texels 4..11 of a 16x16 mask covered: one closed loop through the midpoints of the outline's
// steps, the square with its corners cut (perimeter 4 x 7 + 4 x sqrt(1/2) = 30.8 texels), split
// where it crosses the diagonal between the sheet's triangles; every piece near the square's
// outline, the outside pointing away from it, in the facet's plane.
TEST(AlphaContours, ASquareOfCoveredTexelsIsOneClosedLoopAroundIt) {
  const scene::Image img = mask_image(16, [](int x, int y) { return x >= 4 && x < 12 && y >= 4 && y < 12; });
  Result<esm::SilhouetteGeometry> g = esm::build_alpha_contour_quads(sheet(), kMask, &img);
  ASSERT_TRUE(g) << g.error().to_string();
  const std::vector<Piece> ps = pieces(*g);
  ASSERT_GE(ps.size(), 4u);
  EXPECT_LE(ps.size(), 12u);  // four sides and four cut corners at most, some split by the diagonal
  EXPECT_EQ(g->stats.alpha_contours, ps.size());
  EXPECT_NEAR(total_length(ps) * 16.0, 28.0 + 4.0 * std::sqrt(0.5), 1.0);
  for (const auto& [point, count] : end_counts(ps)) EXPECT_EQ(count, 2) << "open end";
  for (const Piece& p : ps) {
    const glm::vec3 mid = 0.5f * (p.a + p.b);
    EXPECT_LE(from_square(glm::vec2(mid) * 16.0f, 4.0f, 12.0f), 0.75f) << mid.x << "," << mid.y;
    EXPECT_GT(glm::dot(glm::vec2(p.away), glm::vec2(mid) - glm::vec2(0.5f)), 0.0f) << "outside points inwards";
    EXPECT_NEAR(p.away.z, 0.0f, 1e-5f);
    EXPECT_NEAR(p.a.z, 0.0f, 1e-6f);
  }
}

// u from 2 to 0 over the sheet: the texture repeats twice and is mirrored. Two loops, each with
// its outside pointing away from its own square.
TEST(AlphaContours, MirroredAndRepeatedTexturesKeepTheOutsideOutside) {
  const scene::Image img = mask_image(16, [](int x, int y) { return x >= 4 && x < 12 && y >= 4 && y < 12; });
  Result<esm::SilhouetteGeometry> g = esm::build_alpha_contour_quads(sheet(2.0f, 0.0f), kMask, &img);
  ASSERT_TRUE(g) << g.error().to_string();
  const std::vector<Piece> ps = pieces(*g);
  // Each loop: sides of 7 texels (texel centres 4.5 .. 11.5) of 32 along x and of 16 along y,
  // and four cut corners of half a texel each way (the thinning may cut them further).
  const double cut = std::hypot(0.5 / 32.0, 0.5 / 16.0);
  EXPECT_NEAR(total_length(ps), 2.0 * (2.0 * 7.0 / 32.0 + 2.0 * 7.0 / 16.0 + 4.0 * cut), 0.1);
  for (const auto& [point, count] : end_counts(ps)) EXPECT_EQ(count, 2) << "open end";
  for (const Piece& p : ps) {
    const glm::vec2 mid = 0.5f * glm::vec2(p.a + p.b);
    const glm::vec2 centre(mid.x < 0.5f ? 0.25f : 0.75f, 0.5f);
    EXPECT_GT(glm::dot(glm::vec2(p.away), mid - centre), 0.0f) << mid.x << "," << mid.y;
  }
}

// A straight outline at a slope of 0.4 texels a row is a staircase; its contour is thinned to a
// few pieces along the line (within the tolerance plus the half texel of the staircase).
TEST(AlphaContours, AStaircaseIsThinnedToItsLine) {
  auto line_x = [](float y) { return 20.0f + 0.4f * y; };
  const scene::Image img =
      mask_image(64, [&](int x, int y) { return x >= 4 && y >= 4 && y < 60 && x + 0.5f < line_x(y + 0.5f); });
  Result<esm::SilhouetteGeometry> g = esm::build_alpha_contour_quads(sheet(), kMask, &img);
  ASSERT_TRUE(g) << g.error().to_string();
  const std::vector<Piece> ps = pieces(*g);
  EXPECT_LE(ps.size(), 16u) << "the staircase's 56 rows were not thinned";
  // The pieces within the tolerance (plus the staircase's half texel) of the line cover it.
  const float within = esm::kContourTolerance + 0.5f;
  auto from_line = [&](glm::vec2 p) { return std::abs(p.x - line_x(p.y)) / std::sqrt(1.16f); };
  double covered_length = 0.0;
  for (const Piece& p : ps) {
    const glm::vec2 a = glm::vec2(p.a) * 64.0f, b = glm::vec2(p.b) * 64.0f;
    if (from_line(a) > within || from_line(b) > within) continue;
    covered_length += glm::length(b - a);
    EXPECT_GT(p.away.x, 0.0f);  // uncovered to the right of the line
  }
  EXPECT_GE(covered_length, 0.95 * 56.0 * std::sqrt(1.16));
}

TEST(AlphaContours, MasksWithNoOutlineAndMeshesWithNoTriangleGiveNoQuads) {
  for (bool covered : {false, true}) {
    const scene::Image img = mask_image(8, [&](int, int) { return covered; });
    Result<esm::SilhouetteGeometry> g = esm::build_alpha_contour_quads(sheet(), kMask, &img);
    ASSERT_TRUE(g);
    EXPECT_EQ(g->quad_count(), 0u) << (covered ? "covered" : "uncovered");
  }
  const scene::Image img = mask_image(8, [](int x, int) { return x < 4; });
  Result<esm::SilhouetteGeometry> empty = esm::build_alpha_contour_quads(scene::Mesh{.name = "empty"}, kMask, &img);
  ASSERT_TRUE(empty);
  EXPECT_EQ(empty->quad_count(), 0u);
}

// Without a texture the base colour factor's alpha alone decides: a covered mesh casts like an
// opaque one (its edges' quads), an uncovered one casts nothing; the cutoff is glTF's. An image
// short of its pixels counts as none (never read past its end).
TEST(AlphaContours, WithoutATextureTheFactorDecides) {
  scene::Mesh box;
  box.name = "box";
  scene::build::add_box(box, {0, 0, 0}, {1.0f, 0.5f, 0.75f});
  scene::Material m = kMask;
  m.base_color_factor.a = 0.5f;
  Result<esm::SilhouetteGeometry> covered = esm::build_alpha_contour_quads(box, m, nullptr);
  ASSERT_TRUE(covered);
  EXPECT_EQ(covered->quad_count(), 12u);
  m.base_color_factor.a = 0.49f;
  Result<esm::SilhouetteGeometry> hole = esm::build_alpha_contour_quads(box, m, nullptr);
  ASSERT_TRUE(hole);
  EXPECT_EQ(hole->quad_count(), 0u);
  const scene::Image short_of_pixels{.name = "short", .width = 64, .height = 64, .pixels = std::vector<uint8_t>(16, 0)};
  m.base_color_factor.a = 1.0f;
  Result<esm::SilhouetteGeometry> broken = esm::build_alpha_contour_quads(box, m, &short_of_pixels);
  ASSERT_TRUE(broken);
  EXPECT_EQ(broken->quad_count(), 12u);
}

// The factor scales the texture's alpha before the cutoff, as in the depth pass and the reference.
TEST(AlphaContours, TheFactorScalesTheTexturesAlpha) {
  scene::Image img = mask_image(16, [](int x, int) { return x < 8; });
  for (size_t i = 0; i < 16 * 16; ++i)
    if (img.pixels[i * 4 + 3] == 0) img.pixels[i * 4 + 3] = 160;  // 0.63: covered at factor 1
  scene::Material m = kMask;
  Result<esm::SilhouetteGeometry> one = esm::build_alpha_contour_quads(sheet(), m, &img);
  ASSERT_TRUE(one);
  EXPECT_EQ(one->quad_count(), 0u);
  m.base_color_factor.a = 0.7f;  // 255 x 0.7 covered, 160 x 0.7 (0.44) not
  Result<esm::SilhouetteGeometry> scaled = esm::build_alpha_contour_quads(sheet(), m, &img);
  ASSERT_TRUE(scaled);
  EXPECT_GT(scaled->quad_count(), 0u);
}

TEST(AlphaContours, TooManyContourPiecesIsAnErrorNamingTheMeshAndTheLimit) {
  const scene::Image checker = mask_image(32, [](int x, int y) { return ((x / 2) + (y / 2)) % 2 == 0; });
  scene::Mesh m = sheet();
  m.name = "chequered leaf";
  Result<esm::SilhouetteGeometry> g = esm::build_alpha_contour_quads(m, kMask, &checker, {.max_edges = 10});
  ASSERT_FALSE(g);
  const std::string text = g.error().to_string();
  EXPECT_NE(text.find("chequered leaf"), std::string::npos) << text;
  EXPECT_NE(text.find("10"), std::string::npos) << text;
  EXPECT_TRUE(esm::build_alpha_contour_quads(m, kMask, &checker));  // within the shipped limit
}

// A triangle whose texture footprint spans more texel cells than kMaxContourCells, or beyond the
// mesh's budget of traced cells, is skipped and counted, as are triangles with no area in space
// or in the texture.
TEST(AlphaContours, HugeFootprintsAndDegenerateTrianglesAreSkippedAndCounted) {
  const scene::Image img = mask_image(16, [](int x, int) { return x < 8; });
  scene::Mesh huge = sheet(0.0f, 400.0f);
  for (scene::Vertex& v : huge.vertices) v.uv.y *= 400.0f;  // 6400^2 texel cells a triangle
  Result<esm::SilhouetteGeometry> g = esm::build_alpha_contour_quads(huge, kMask, &img);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->stats.alpha_skipped, 2u);
  EXPECT_EQ(g->quad_count(), 0u);

  // The mesh's budget: the first triangle (16^2 + border cells) fits 400 cells, the second not.
  Result<esm::SilhouetteGeometry> budget = esm::build_alpha_contour_quads(sheet(), kMask, &img, {.max_contour_cells = 400});
  ASSERT_TRUE(budget);
  EXPECT_EQ(budget->stats.alpha_skipped, 1u);
  EXPECT_GT(budget->quad_count(), 0u);

  scene::Mesh bad = sheet();
  for (scene::Vertex& v : bad.vertices) v.uv = {0.5f, 0.5f};  // no texture area
  bad.indices.insert(bad.indices.end(), {0, 0, 1, 0, 1, 7});  // two corners alike; out of range
  Result<esm::SilhouetteGeometry> d = esm::build_alpha_contour_quads(bad, kMask, &img);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->stats.degenerate_triangles, 4u);
  EXPECT_EQ(d->quad_count(), 0u);
}
