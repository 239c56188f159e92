// The CPU silhouette builder (techniques/esm/silhouette): welding, edge classification, the
// quads' silhouette test as the vertex shader runs it, and bad input. No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "scene/mesh_builder.h"
#include "techniques/esm/silhouette/edge_adjacency.h"
#include "techniques/esm/silhouette/silhouette_quads.h"

using namespace penumbra;
using esm::SilhouetteQuad;

namespace {

scene::Mesh box_mesh() {
  scene::Mesh m;
  m.name = "box";
  scene::build::add_box(m, {0, 0, 0}, {1.0f, 0.5f, 0.75f});
  return m;
}

// What the finding pass and the vertex shader decide: a quad has area when the light
// (homogeneous: a point (p, 1) or the direction towards a parallel light (-d, 0)) is in front of
// exactly one of its planes.
bool opens(const esm::SilhouetteGeometry& g, size_t quad, const glm::vec4& light) {
  return esm::is_silhouette(g.quads[quad], light);
}

// The silhouette a light sees: the opened quads' edges, as welded-position pairs, and how many
// opened edges meet at each end point (a closed silhouette loop has an even count everywhere).
struct Silhouette {
  size_t edges = 0;
  std::map<std::tuple<float, float, float>, int> degree;
};
Silhouette silhouette(const esm::SilhouetteGeometry& g, const glm::vec4& light) {
  Silhouette s;
  auto key = [](const glm::vec3& p) {  // round so welded ends compare equal
    return std::make_tuple(std::round(p.x * 1e4f), std::round(p.y * 1e4f), std::round(p.z * 1e4f));
  };
  for (size_t q = 0; q < g.quad_count(); ++q) {
    if (!opens(g, q, light)) continue;
    ++s.edges;
    ++s.degree[key(g.quads[q].a)];
    ++s.degree[key(g.quads[q].b)];
  }
  return s;
}

glm::vec4 parallel_light(const glm::vec3& direction) { return glm::vec4(-glm::normalize(direction), 0.0f); }

}  // namespace

TEST(SilhouetteBuilder, BoxFacesSplitAtUvSeamsWeldIntoTwelveConvexEdges) {
  const scene::Mesh box = box_mesh();
  ASSERT_EQ(box.vertices.size(), 24u);  // four per face, like a glTF cube with per-face UVs
  Result<esm::SilhouetteGeometry> g = esm::build_silhouette_quads(box);
  ASSERT_TRUE(g) << g.error().to_string();
  const esm::SilhouetteStats& s = g->stats;
  EXPECT_EQ(s.welded_vertices, 8u);
  EXPECT_EQ(s.edges, 18u);
  EXPECT_EQ(s.coplanar, 6u);  // face diagonals
  EXPECT_EQ(s.convex, 12u);
  EXPECT_EQ(s.beveled, 0u);   // 90 degrees: the bisector is still within 45 degrees
  EXPECT_EQ(s.open, 0u);
  EXPECT_EQ(s.quads, 12u);
  EXPECT_EQ(g->quads.size(), 12u);
  // A generic light sees a hexagonal outline: six silhouette edges in one closed loop.
  const Silhouette sil = silhouette(*g, parallel_light({-1.0f, -2.0f, -3.0f}));
  EXPECT_EQ(sil.edges, 6u);
  for (const auto& [p, n] : sil.degree) EXPECT_EQ(n, 2);
  // Every quad's extrusion points away from the box (its centre is the origin).
  for (const SilhouetteQuad& q : g->quads) EXPECT_GT(glm::dot(q.extrusion, q.a + q.b), 0.0f);
}

TEST(SilhouetteBuilder, SphereSeamWeldsIntoAClosedSurfaceWithClosedSilhouetteLoops) {
  scene::Mesh sphere;
  sphere.name = "ball";
  scene::build::add_sphere(sphere, {0, 1, 0}, 0.5f, 24, 12);  // the phi = 0 / 2 pi column is duplicated
  Result<esm::SilhouetteGeometry> welded = esm::build_silhouette_quads(sphere);
  ASSERT_TRUE(welded);
  EXPECT_EQ(welded->stats.open, 0u);
  EXPECT_EQ(welded->stats.non_manifold, 0u);
  EXPECT_EQ(welded->stats.concave, 0u);
  // Exact-position welding only: cos/sin(2 pi) differ from cos/sin(0) in the last bits, the seam
  // stays open (what an unwelded glTF sphere looks like to an index-based adjacency).
  Result<esm::SilhouetteGeometry> exact = esm::build_silhouette_quads(sphere, {.weld_tolerance = 0.0f});
  ASSERT_TRUE(exact);
  EXPECT_GT(exact->stats.open, 0u);
  for (const glm::vec3 dir : {glm::vec3(0, -1, 0), glm::vec3(-0.3f, -1, 0.2f), glm::vec3(1, -0.2f, 0.1f)}) {
    const Silhouette sil = silhouette(*welded, parallel_light(dir));
    EXPECT_GE(sil.edges, 24u) << "the silhouette goes round the sphere";
    for (const auto& [p, n] : sil.degree) EXPECT_EQ(n % 2, 0) << "open silhouette loop";
  }
}

TEST(SilhouetteBuilder, OpenEdgesOfASheetAreItsOutlineFromEitherSide) {
  scene::Mesh quad;
  quad.name = "sheet";
  scene::build::add_ground(quad, {0, 0, 0}, 2.0f, 1.0f);  // two triangles, four boundary edges
  Result<esm::SilhouetteGeometry> g = esm::build_silhouette_quads(quad);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->stats.open, 4u);
  EXPECT_EQ(g->stats.coplanar, 1u);
  EXPECT_EQ(g->stats.quads, 8u);  // two per open edge (the 180-degree fold's bevel)
  for (const glm::vec3 dir : {glm::vec3(0.2f, -1, 0.1f), glm::vec3(0.2f, 1, 0.1f)}) {  // above and below
    const Silhouette sil = silhouette(*g, parallel_light(dir));
    EXPECT_EQ(sil.edges, 4u) << "exactly one quad of each bevel pair opens";
    for (const auto& [p, n] : sil.degree) EXPECT_EQ(n, 2);
  }
  // A box with its top face missing: the rim is open, everything else as before.
  scene::Mesh cup = box_mesh();
  cup.indices.resize(cup.indices.size() - 6);  // add_box's last face is +Z
  Result<esm::SilhouetteGeometry> c = esm::build_silhouette_quads(cup);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->stats.open, 4u);
  EXPECT_EQ(c->stats.convex, 8u);
}

TEST(SilhouetteBuilder, SharpEdgesGetBevelsWhoseExtrusionKeeps70PercentAndPointsOut) {
  // A thin wedge (ridge angle ~23 degrees): its two long slanted faces meet at a sharp edge.
  scene::Mesh wedge;
  wedge.name = "wedge";
  const glm::vec3 p[6] = {{-1, 0, -0.2f}, {-1, 0, 0.2f}, {-1, 1, 0}, {1, 0, -0.2f}, {1, 0, 0.2f}, {1, 1, 0}};
  for (const glm::vec3& v : p) wedge.vertices.push_back({v, {0, 1, 0}, {0, 0}});
  wedge.indices = {0, 1, 2, 3, 5, 4, 0, 4, 1, 0, 3, 4, 1, 5, 2, 1, 4, 5, 0, 5, 3, 0, 2, 5};  // outward
  Result<esm::SilhouetteGeometry> g = esm::build_silhouette_quads(wedge);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->stats.convex, 9u);
  EXPECT_EQ(g->stats.beveled, 3u);  // the ridge and the two long bottom edges (~101 degrees)
  EXPECT_FALSE(g->stats.flipped);
  // Wound inside out, a closed mesh has a negative volume: the builder turns it the right way.
  scene::Mesh inside_out = wedge;
  for (size_t t = 0; t < inside_out.indices.size(); t += 3) std::swap(inside_out.indices[t + 1], inside_out.indices[t + 2]);
  Result<esm::SilhouetteGeometry> f = esm::build_silhouette_quads(inside_out);
  ASSERT_TRUE(f);
  EXPECT_TRUE(f->stats.flipped);
  EXPECT_EQ(f->stats.convex, 9u);
  EXPECT_EQ(f->stats.concave, 0u);
  const glm::vec3 centre(0, 0.33f, 0);
  std::mt19937 rng(7);
  std::normal_distribution<float> n01;
  for (int trial = 0; trial < 500; ++trial) {
    const glm::vec3 l = glm::normalize(glm::vec3(n01(rng), n01(rng), n01(rng)));  // towards the light
    for (size_t q = 0; q < g->quad_count(); ++q) {
      if (!opens(*g, q, glm::vec4(l, 0.0f))) continue;
      const SilhouetteQuad& v = g->quads[q];
      const glm::vec3 across = v.extrusion - glm::dot(v.extrusion, l) * l;  // seen from the light
      EXPECT_GE(glm::length(across), 0.7071f - 1e-4f) << "trial " << trial;
      const glm::vec3 mid = 0.5f * (v.a + v.b) - centre;
      EXPECT_GT(glm::dot(across, mid - glm::dot(mid, l) * l), 0.0f) << "extrusion points out";
    }
  }
}

TEST(SilhouetteBuilder, ConcaveEdgesGetNoQuads) {
  // An L-shaped prism: one concave (inner corner) edge along its length.
  scene::Mesh l;
  l.name = "ell";
  scene::build::add_box(l, {0, 0.5f, 0}, {0.5f, 0.5f, 1.0f});
  scene::build::add_box(l, {1.0f, 0.25f, 0}, {0.5f, 0.25f, 1.0f});  // touching, not merged: the
  // two boxes share no edge, so each is closed on its own and there is nothing concave...
  Result<esm::SilhouetteGeometry> apart = esm::build_silhouette_quads(l);
  ASSERT_TRUE(apart);
  EXPECT_EQ(apart->stats.concave, 0u);
  // ...whereas a real L cross-section extruded along z has exactly one concave edge.
  scene::Mesh ell;
  ell.name = "ell";
  const glm::vec2 outline[6] = {{0, 0}, {2, 0}, {2, 0.5f}, {1, 0.5f}, {1, 1}, {0, 1}};  // CCW, reflex at (1, .5)
  for (float z : {-1.0f, 1.0f})
    for (const glm::vec2& o : outline) ell.vertices.push_back({{o.x, o.y, z}, {0, 0, 1}, {0, 0}});
  for (uint32_t i = 0; i < 6; ++i) {  // sides
    const uint32_t j = (i + 1) % 6;
    ell.indices.insert(ell.indices.end(), {i, j, j + 6, i, j + 6, i + 6});
  }
  // Caps (fans that avoid the reflex corner): z = +1 counter-clockwise, z = -1 reversed.
  const uint32_t cap[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
  for (const auto& t : cap) {
    ell.indices.insert(ell.indices.end(), {t[0] + 6, t[1] + 6, t[2] + 6});
    ell.indices.insert(ell.indices.end(), {t[0], t[2], t[1]});
  }
  Result<esm::SilhouetteGeometry> g = esm::build_silhouette_quads(ell);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->stats.open, 0u);
  EXPECT_EQ(g->stats.concave, 1u);
}

TEST(SilhouetteBuilder, NonManifoldAndInconsistentEdgesAreTreatedAsOpen) {
  scene::Mesh fin;  // three triangles on the edge (0,0,0)-(1,0,0)
  fin.name = "fin";
  const glm::vec3 p[5] = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0.3f}, {0.5f, 0, 1}};
  for (const glm::vec3& v : p) fin.vertices.push_back({v, {0, 1, 0}, {0, 0}});
  fin.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  Result<esm::SilhouetteGeometry> g = esm::build_silhouette_quads(fin);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->stats.non_manifold, 1u);
  scene::Mesh flipped;  // two triangles running their shared edge the same way
  flipped.name = "flipped";
  flipped.vertices = fin.vertices;
  flipped.indices = {0, 1, 2, 0, 1, 3};
  g = esm::build_silhouette_quads(flipped);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->stats.inconsistent, 1u);
  EXPECT_EQ(g->stats.open, 4u);
}

TEST(SilhouetteBuilder, DegenerateAndZeroAreaTrianglesAreSkippedNotFatal) {
  scene::Mesh m = box_mesh();
  m.name = "dirty";
  const uint32_t n = static_cast<uint32_t>(m.vertices.size());
  m.vertices.push_back({{0.25f, 0.125f, 0.75f}, {0, 1, 0}, {0, 0}});  // on the +Z face's diagonal
  m.vertices.push_back({{std::numeric_limits<float>::quiet_NaN(), 0, 0}, {0, 1, 0}, {0, 0}});
  m.indices.insert(m.indices.end(), {0, 0, 1});          // repeated index
  m.indices.insert(m.indices.end(), {0, 1, 0});          // repeated index
  m.indices.insert(m.indices.end(), {n - 4, n - 2, n});  // the +Z face's corners a, d and a point
                                                         // between them: zero area
  m.indices.insert(m.indices.end(), {0, 1, n + 1});      // NaN corner
  m.indices.insert(m.indices.end(), {0, 1, 9999});       // index out of range
  Result<esm::SilhouetteGeometry> g = esm::build_silhouette_quads(m);
  ASSERT_TRUE(g) << g.error().to_string();
  EXPECT_EQ(g->stats.degenerate_triangles, 5u);
  EXPECT_EQ(g->stats.facets + g->stats.degenerate_triangles, m.indices.size() / 3);
  // Welding two corners of a triangle together also makes it degenerate.
  scene::Mesh sliver;
  sliver.name = "sliver";
  sliver.vertices = {{{0, 0, 0}, {0, 1, 0}, {0, 0}}, {{1e-9f, 0, 0}, {0, 1, 0}, {0, 0}}, {{0, 1, 0}, {0, 1, 0}, {0, 0}},
                     {{5, 5, 5}, {0, 1, 0}, {0, 0}}};
  sliver.indices = {0, 1, 2, 0, 2, 3};
  g = esm::build_silhouette_quads(sliver);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->stats.degenerate_triangles, 1u);
}

TEST(SilhouetteBuilder, MeshesWithNoClosedEdgeOrNoTriangleAtAllWork) {
  scene::Mesh soup;  // separate triangles far apart: every edge open
  soup.name = "soup";
  for (int t = 0; t < 5; ++t)
    for (int k = 0; k < 3; ++k) {
      soup.vertices.push_back({{10.0f * t + (k == 1), 0.0f, (k == 2) ? 1.0f : 0.0f}, {0, 1, 0}, {0, 0}});
      soup.indices.push_back(static_cast<uint32_t>(soup.vertices.size() - 1));
    }
  Result<esm::SilhouetteGeometry> g = esm::build_silhouette_quads(soup);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->stats.open, 15u);
  EXPECT_EQ(g->stats.quads, 30u);
  for (scene::Mesh empty : {scene::Mesh{}, scene::Mesh{.name = "points", .vertices = soup.vertices}}) {
    g = esm::build_silhouette_quads(empty);
    ASSERT_TRUE(g);
    EXPECT_EQ(g->stats.quads, 0u);
  }
  scene::Mesh only_degenerate;
  only_degenerate.name = "flat";
  only_degenerate.vertices = {{{0, 0, 0}, {0, 1, 0}, {0, 0}}, {{1, 0, 0}, {0, 1, 0}, {0, 0}}, {{2, 0, 0}, {0, 1, 0}, {0, 0}}};
  only_degenerate.indices = {0, 1, 2, 2, 1, 0, 0, 0, 0, 7, 8};  // collinear, repeated, and a trailing partial triangle
  g = esm::build_silhouette_quads(only_degenerate);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->stats.facets, 0u);
  EXPECT_EQ(g->stats.quads, 0u);
}

TEST(SilhouetteBuilder, MoreEdgesThanTheLimitIsAnErrorNamingTheMeshAndTheLimit) {
  // The box has 18 welded edges; a limit of 17 refuses it, 18 takes it.
  Result<esm::SilhouetteGeometry> g = esm::build_silhouette_quads(box_mesh(), {.max_edges = 17});
  ASSERT_FALSE(g);
  const std::string msg = g.error().to_string();
  EXPECT_NE(msg.find("mesh 'box'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("has 18 edges"), std::string::npos) << msg;
  EXPECT_NE(msg.find("at most 17 edges per mesh"), std::string::npos) << msg;
  EXPECT_EQ(g.error().exit_code(), 2);
  EXPECT_TRUE(esm::build_silhouette_quads(box_mesh(), {.max_edges = 18}));
  scene::Scene s;
  s.materials.push_back({});
  s.meshes = {scene::Mesh{.name = "tiny"}, box_mesh()};
  Result<std::vector<esm::SilhouetteGeometry>> all = esm::build_scene_silhouettes(s, {.max_edges = 17});
  ASSERT_FALSE(all);
  EXPECT_NE(all.error().to_string().find("scene mesh 1 'box'"), std::string::npos) << all.error().to_string();
  // The shipped limit is 2^24 edges, and the message names it.
  EXPECT_EQ(esm::kMaxEdgesPerMesh, size_t{1} << 24);
  EXPECT_EQ(esm::SilhouetteOptions{}.max_edges, esm::kMaxEdgesPerMesh);
}

// Masked meshes get their mask's contour (alpha_contours_test.cpp): with no texture and a covered
// factor, their edges' quads; with the contours off, none. Blended materials cast as opaque.
TEST(SilhouetteBuilder, AlphaMaskedMeshesCastTheirMasksContourOrNothing) {
  scene::Scene s;
  s.materials = {scene::Material{}, scene::Material{.alpha_mode = scene::AlphaMode::mask},
                 scene::Material{.alpha_mode = scene::AlphaMode::blend},
                 scene::Material{.base_color_texture = 0, .alpha_mode = scene::AlphaMode::mask}};
  scene::Image hole{.name = "hole", .width = 2, .height = 2, .pixels = std::vector<uint8_t>(16, 255)};
  hole.pixels[3] = 0;  // texel (0, 0) uncovered
  s.images = {hole};
  for (uint32_t m = 0; m < 4; ++m) {
    s.meshes.push_back(box_mesh());
    s.meshes.back().material = m;
  }
  Result<std::vector<esm::SilhouetteGeometry>> all = esm::build_scene_silhouettes(s);
  ASSERT_TRUE(all);
  EXPECT_EQ((*all)[0].quad_count(), 12u);
  EXPECT_EQ((*all)[1].quad_count(), 12u);  // mask, no texture, factor alpha 1: covered
  EXPECT_EQ((*all)[2].quad_count(), 12u);  // blend casts as opaque in every shadow map
  EXPECT_GT((*all)[3].stats.alpha_contours, 0u);
  EXPECT_EQ((*all)[3].quad_count(), 2 * (*all)[3].stats.alpha_contours);
  Result<std::vector<esm::SilhouetteGeometry>> off = esm::build_scene_silhouettes(s, {.alpha_contours = false});
  ASSERT_TRUE(off);
  EXPECT_EQ((*off)[0].quad_count(), 12u);
  EXPECT_EQ((*off)[1].quad_count(), 0u);
  EXPECT_EQ((*off)[3].quad_count(), 0u);
}
