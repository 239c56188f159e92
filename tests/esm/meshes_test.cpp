// Meshes that are not closed and tidy: a single-sided sheet (open edges), solids split at UV seams
// (a box with four vertices per face, a UV sphere and a capped cylinder: glTF-style split
// vertices), and bad input (degenerate and zero-area triangles, a triangle soup with no closed
// edge). Their shadows must be right: solid inside, lit outside, sharp and correct at the edges.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "esm_rig.h"
#include "esm_scenes.h"
#include "metrics/edge_error.h"
#include "scene/mesh_builder.h"

using namespace penumbra;

namespace {

void add(scene::Scene& s, scene::Mesh m) {
  m.material = 0;
  s.meshes.push_back(std::move(m));
  s.instances.push_back({static_cast<uint32_t>(s.meshes.size() - 1), glm::mat4(1.0f)});
}

scene::Scene awkward_meshes(bool bad_input) {
  scene::Scene s;
  s.name = "awkward";
  s.materials.push_back({.base_color_factor = glm::vec4(0.7f)});
  scene::Mesh ground;
  ground.name = "ground";
  scene::build::add_ground(ground, {0, 0, 0}, 8.0f, 8.0f);
  add(s, ground);
  scene::Mesh sheet;  // one-sided, tilted: four open edges
  sheet.name = "sheet";
  scene::build::add_ground(sheet, {0, 0, 0}, 1.2f, 0.8f);
  for (scene::Vertex& v : sheet.vertices) v.position = glm::vec3(v.position.x - 1.2f, 1.2f + 0.3f * v.position.z, v.position.z - 0.8f);
  add(s, sheet);
  scene::Mesh seams;  // split at every UV seam
  seams.name = "seamed";
  scene::build::add_box(seams, {1.2f, 0.8f, -0.6f}, {0.35f, 0.35f, 0.35f});
  scene::build::add_sphere(seams, {-0.6f, 1.0f, 1.0f}, 0.45f, 24, 12);
  scene::build::add_cylinder(seams, {1.0f, 0.6f, 1.1f}, {2.0f, 1.0f, 1.3f}, 0.2f, 16);
  add(s, seams);
  if (bad_input) {
    scene::Mesh dirty;  // a box with degenerate and zero-area triangles mixed in
    dirty.name = "dirty";
    scene::build::add_box(dirty, {-1.8f, 0.7f, 1.8f}, {0.3f, 0.3f, 0.3f});
    dirty.indices.insert(dirty.indices.end(), {0, 0, 1, 2, 2, 2, 0, 1, 0});  // repeated corners
    // Zero area: two opposite corners of a face and the face's centre between them.
    dirty.vertices.push_back({0.5f * (dirty.vertices[0].position + dirty.vertices[2].position), {0, 1, 0}, {0, 0}});
    dirty.indices.insert(dirty.indices.end(), {0, 2, static_cast<uint32_t>(dirty.vertices.size() - 1)});
    add(s, dirty);
    scene::Mesh soup;  // separate triangles: no closed edge at all
    soup.name = "soup";
    for (int t = 0; t < 6; ++t) {
      const glm::vec3 o(1.6f + 0.25f * (t % 3), 1.4f, -1.8f + 0.3f * (t / 3));
      for (const glm::vec3& p : {o, o + glm::vec3(0.2f, 0, 0), o + glm::vec3(0, 0.05f, 0.2f)}) {
        soup.vertices.push_back({p, {0, 1, 0}, {0, 0}});
        soup.indices.push_back(static_cast<uint32_t>(soup.vertices.size() - 1));
      }
    }
    add(s, soup);
  }
  s.bounds = scene::compute_bounds(s);
  s.light.type = scene::LightType::spot;
  s.light.position = {2.5f, 7.0f, 3.0f};
  s.light.direction = glm::normalize(-s.light.position);
  s.light.spot_angle = glm::radians(40.0f);
  s.light.size = 0.0f;
  s.camera = test::view({0.0f, 4.2f, 3.2f}, {0.0f, 0.3f, 0.0f}, 55.0f);
  return s;
}

struct Interior {
  float brightest_shadow = 0.0f;  // esm, in the reference's shadow
  size_t shadowed = 0;
  size_t dark_in_light = 0;       // esm dark in the reference's light where the plain map is lit
};

// Receivers 2 px or more from the reference's edges. In the light, the plain map has acne of its
// own at a few box edges (the depth pass and its bias are the same): only darkness esm adds counts.
Interior interior(const metrics::MaskImage& mask, const metrics::MaskImage& plain, const metrics::MaskImage& reference,
                  const metrics::CoverageMask& coverage) {
  const metrics::CoverageMask edges = metrics::edge_band(reference, coverage, 2.0f);
  Interior in;
  for (size_t i = 0; i < mask.pixels.size(); ++i) {
    if (!coverage[i] || edges[i]) continue;
    if (reference.pixels[i] < 0.5f) {
      in.brightest_shadow = std::max(in.brightest_shadow, mask.pixels[i]);
      ++in.shadowed;
    } else if (mask.pixels[i] < 0.95f && plain.pixels[i] == 1.0f) {
      ++in.dark_in_light;
    }
  }
  return in;
}

void check(bool bad_input) {
  const scene::Scene s = awkward_meshes(bad_input);
  test::EsmRig rig(256, 192, 256);
  rig.set_scene(s);
  rig.use("esm");
  rig.render();
  const metrics::MaskImage esm = rig.shadow_mask();
  for (float v : esm.pixels) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
  const metrics::CoverageMask coverage = rig.coverage();
  const metrics::MaskImage reference = test::exact_hard_reference(rig, s);
  Result<metrics::EdgeError> e_esm = metrics::edge_error(esm, reference, coverage);
  rig.use("hard");
  rig.render();
  const metrics::MaskImage hard = rig.shadow_mask();
  Result<metrics::EdgeError> e_hard = metrics::edge_error(hard, reference, coverage);
  const Interior in = interior(esm, hard, reference, coverage);
  ASSERT_TRUE(e_esm && e_hard);
  std::printf("[ measure  ] %s: %zu shadow pixels, brightest %.3f; %zu dark pixels in the light; edge error esm %.4f "
              "hard %.4f\n", bad_input ? "with bad input" : "open edges and seams", in.shadowed, in.brightest_shadow,
              in.dark_in_light, e_esm->error, e_hard->error);
  EXPECT_GT(in.shadowed, 1000u);
  EXPECT_LE(in.brightest_shadow, 0.05f) << "light inside a shadow";
  EXPECT_EQ(in.dark_in_light, 0u) << "shadow where there is none";
  EXPECT_LT(e_esm->error, 0.9 * e_hard->error);
  test::save_for_inspection(bad_input ? "awkward_bad" : "awkward", esm);
}

}  // namespace

TEST(EsmMeshes, OpenEdgesAndUvSeamsGetCorrectSilhouettes) { check(false); }

TEST(EsmMeshes, DegenerateTrianglesAndTriangleSoupsRenderCorrectly) { check(true); }

// Split vertices must not become silhouettes: a box with four vertices per face and a UV sphere,
// lit by a directional light, mark only a band around their projected outlines in the silhouette
// mask. (Without welding every box edge and the sphere's seam meridian would be an open edge,
// a silhouette from every light, banded across the middle of the projections.)
TEST(EsmMeshes, SeamedSolidsMarkOnlyTheirOutline) {
  scene::Scene s;
  s.materials.push_back({});
  scene::Mesh box, ball;
  box.name = "box";
  ball.name = "ball";
  scene::build::add_box(box, {-1.0f, 1.0f, 0.0f}, {0.6f, 0.6f, 0.6f});
  scene::build::add_sphere(ball, {1.0f, 1.0f, 0.0f}, 0.6f, 32, 16);
  add(s, box);
  add(s, ball);
  s.bounds = scene::compute_bounds(s);
  s.light = scene::directional_light_for(s.bounds, glm::normalize(glm::vec3(-0.3f, -1.0f, -0.45f)), 0.0f);
  s.camera = test::view({0, 3, 4}, {0, 1, 0}, 50.0f);
  constexpr int kMap = 256;
  test::EsmRig rig(64, 48, kMap);
  rig.set_scene(s);
  rig.use("esm");
  rig.render();
  const metrics::MaskImage band = rig.read("esm_silhouette_mask");  // rows top to bottom
  const scene::ShadowFrustum f = scene::shadow_frustum(s.light, s.bounds);
  auto texel = [&](const glm::vec3& p) {  // map texel coordinates, rows top to bottom
    const glm::vec4 c = f.view_proj * glm::vec4(p, 1.0f);
    return glm::vec2((c.x * 0.5f + 0.5f) * kMap, (0.5f - c.y * 0.5f) * kMap);
  };
  // The sphere: its outline is a circle (orthographic), radius in texels.
  const glm::vec2 ball_centre = texel({1.0f, 1.0f, 0.0f});
  const float ball_radius = 0.6f * kMap / f.width_world;
  // The box: inside the projection of its inscribed ball (radius = half extent) is far from its outline.
  const glm::vec2 box_centre = texel({-1.0f, 1.0f, 0.0f});
  const float box_inner = 0.6f * kMap / f.width_world;
  size_t marked = 0, ball_interior = 0, box_interior = 0;
  for (int y = 0; y < kMap; ++y)
    for (int x = 0; x < kMap; ++x) {
      if (band.at(x, y) < 0.5f) continue;
      ++marked;
      const glm::vec2 t(x + 0.5f, y + 0.5f);
      if (glm::length(t - ball_centre) < ball_radius - 3.5f) ++ball_interior;
      if (glm::length(t - box_centre) < box_inner - 3.5f) ++box_interior;
    }
  std::printf("[ measure  ] %zu texels in silhouette bands; %zu inside the ball's outline, %zu inside the box's\n", marked,
              ball_interior, box_interior);
  EXPECT_GT(marked, 200u);
  EXPECT_EQ(ball_interior, 0u);
  EXPECT_EQ(box_interior, 0u);
}
