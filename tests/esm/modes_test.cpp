// esm's switches: comparison mode (no quads = the ordinary shadow map, the paper's Figure 8),
// the two-pass fallback (the same map as one MAX-blended pass), the debug views, and what the
// binary / ramp settings do.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "esm_rig.h"
#include "esm_scenes.h"
#include "scene/builtin_scenes.h"

using namespace penumbra;

namespace {

float max_difference(const metrics::MaskImage& a, const metrics::MaskImage& b) {
  float m = 0.0f;
  for (size_t i = 0; i < a.pixels.size(); ++i) m = std::max(m, std::abs(a.pixels[i] - b.pixels[i]));
  return m;
}

size_t count_between(const metrics::MaskImage& m, float lo, float hi) {
  return static_cast<size_t>(std::count_if(m.pixels.begin(), m.pixels.end(), [&](float v) { return v > lo && v < hi; }));
}

}  // namespace

// Figure 8: "scene was rendered with the ESM, but with rendering of silhouette quads disabled".
// With the quads off, esm is plain shadow mapping, pixel for pixel the `hard` technique with the
// same biases (directional and spot lights); palms' alpha-masked fronds too (their alpha tested as
// every shadow map does, not at the nearest texel the contours' quads need).
TEST(EsmModes, WithoutQuadsItIsThePlainShadowMapExactly) {
  for (const auto& [name, spot] : {std::pair{"poles", false}, std::pair{"poles", true}, std::pair{"palms", false}}) {
    scene::Scene s = *scene::make_builtin_scene(name);
    if (spot) {
      s.light.type = scene::LightType::spot;
      s.light.spot_angle = glm::radians(45.0f);
    }
    test::EsmRig rig(192, 144, 256);
    rig.set_scene(s);
    rig.use("hard");
    rig.render();
    const metrics::MaskImage hard = rig.shadow_mask();
    rig.use("esm");
    rig.set({"silhouette_quads=false"});
    rig.render();
    const metrics::MaskImage plain = rig.shadow_mask();
    EXPECT_EQ(max_difference(plain, hard), 0.0f) << name << (spot ? " spot" : " directional");
    EXPECT_EQ(count_between(plain, 0.0f, 1.0f), 0u) << "binary, like any plain shadow map";
    rig.set({"silhouette_quads=true"});
    rig.render();
    EXPECT_GT(count_between(rig.shadow_mask(), 0.02f, 0.98f), 20u) << "with quads the edges are anti-aliased";
  }
}

// The paper's fallback for hardware without MAX blending with those factors: one pass that
// overwrites, then a MAX pass. Both resolve overlaps to the same map.
TEST(EsmModes, TwoPassFallbackGivesTheSameShadow) {
  test::EsmRig rig(192, 144, 256);
  rig.set_scene(test::crossed_pipes(0.12f, 0.3f));
  rig.use("esm");
  rig.render();
  const metrics::MaskImage one = rig.shadow_mask();
  const metrics::MaskImage one_mask = rig.read("esm_silhouette_mask");
  rig.set({"overlap_resolve=two_pass"});
  rig.render();
  EXPECT_LT(max_difference(rig.shadow_mask(), one), 1e-3f);
  EXPECT_EQ(max_difference(rig.read("esm_silhouette_mask"), one_mask), 0.0f);
  bool has_overwrite_pass = false;
  for (const auto& p : rig.session().plan().passes) has_overwrite_pass |= p.name == "silhouette_quads_overwrite";
  EXPECT_TRUE(has_overwrite_pass);
}

// Finding the silhouettes first (a compute pass, then only they are drawn, or their texels
// written by a second compute pass with image atomics) or drawing every quad and letting the
// vertex shader collapse the others (the paper) writes the same map, bit for bit: all its
// channels (edge value, edge depth, nearest edge), and so the same shadow. Every built-in scene, and a
// point light's six faces.
TEST(EsmModes, FindingSilhouettesFirstWritesTheSameMapAsDrawingEveryQuad) {
  std::vector<std::pair<std::string, scene::Scene>> scenes;
  for (const char* name : {"ball", "fence", "poles", "colonnade", "palms", "showcase"})
    scenes.emplace_back(name, *scene::make_builtin_scene(name));
  scenes.emplace_back("room lit from inside", test::point_lit_room(glm::vec3(0.6f, -0.4f, 0.3f)));
  for (const auto& [name, s] : scenes) {
    test::EsmRig rig(160, 120, name == "room lit from inside" ? 768 : 256);
    rig.set_scene(s);
    rig.use("esm");
    rig.set({"silhouette_finding=all"});
    rig.render();
    const metrics::MaskImage all_shadow = rig.shadow_mask();
    const metrics::MaskImage all_distance = rig.read("esm_edge_distance");
    const metrics::MaskImage all_marks = rig.read("esm_silhouette_mask");
    const metrics::MaskImage all_edge = rig.read("esm_edge"), all_edge_depth = rig.read("esm_edge_depth");
    const metrics::MaskImage all_edge_near = rig.read("esm_edge_near");
    for (const char* finding : {"silhouette_finding=gpu", "silhouette_finding=compute"}) {
      rig.set({finding});
      rig.render();
      EXPECT_EQ(max_difference(rig.read("esm_edge"), all_edge), 0.0f) << name << ", " << finding;
      EXPECT_EQ(max_difference(rig.read("esm_edge_depth"), all_edge_depth), 0.0f) << name << ", " << finding;
      EXPECT_EQ(max_difference(rig.read("esm_edge_near"), all_edge_near), 0.0f) << name << ", " << finding;
      EXPECT_EQ(max_difference(rig.read("esm_edge_distance"), all_distance), 0.0f) << name << ", " << finding;
      EXPECT_EQ(max_difference(rig.read("esm_silhouette_mask"), all_marks), 0.0f) << name << ", " << finding;
      EXPECT_EQ(max_difference(rig.shadow_mask(), all_shadow), 0.0f) << name << ", " << finding;
    }
    size_t marked = 0;
    for (float m : all_marks.pixels) marked += m > 0.5f ? 1 : 0;
    EXPECT_GT(marked, 0u) << name << ": no silhouette to compare";
    // The paper's two-pass fallback finds the silhouettes for each of its passes (its overwriting
    // pass draws them whichever way the MAX pass writes).
    for (const char* finding : {"silhouette_finding=gpu", "silhouette_finding=compute"}) {
      rig.set({finding, "overlap_resolve=two_pass"});
      rig.render();
      EXPECT_EQ(max_difference(rig.read("esm_silhouette_mask"), all_marks), 0.0f) << name << ", two passes, " << finding;
      EXPECT_LT(max_difference(rig.shadow_mask(), all_shadow), 1e-3f) << name << ", two passes, " << finding;
    }
  }
}

// The debug views: the silhouette mask marks a band around every silhouette and nothing else;
// the edge-distance channel stays within the quad band (texels).
// A scene without caster edges (a mesh with no triangles) has no quads to find, draw or write:
// every way leaves the map at "no edge" without a GL error, and the mask is lit (at 2048^2, where
// auto writes by compute).
TEST(EsmModes, ASceneWithoutQuadsIsLitEveryWay) {
  scene::Scene s = *scene::make_builtin_scene("ball");
  s.meshes.resize(1);
  s.meshes[0].indices.clear();
  s.meshes[0].vertices.clear();
  s.instances = {{0, glm::mat4(1.0f)}};
  test::EsmRig rig(64, 48, 2048);
  rig.set_scene(s);
  rig.use("esm");
  for (const char* finding : {"silhouette_finding=auto", "silhouette_finding=compute", "silhouette_finding=gpu",
                              "silhouette_finding=all"}) {
    rig.set({finding});
    while (glGetError() != GL_NO_ERROR) {
    }
    const Status status = rig.try_render();
    ASSERT_TRUE(status) << finding << ": " << status.error().to_string();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << finding;
    EXPECT_EQ(count_between(rig.shadow_mask(), -1.0f, 0.999f), 0u) << finding << ": all lit";
  }
}

TEST(EsmModes, DebugViewsShowTheSilhouetteBandAndItsDistances) {
  test::EsmRig rig(128, 96, 256);
  rig.set_scene(*scene::make_builtin_scene("ball"));
  rig.use("esm");
  rig.render();
  const metrics::MaskImage mask = rig.read("esm_silhouette_mask");
  const metrics::MaskImage distance = rig.read("esm_edge_distance");
  ASSERT_EQ(mask.width, 256);
  size_t band = 0;
  for (size_t i = 0; i < mask.pixels.size(); ++i) {
    ASSERT_TRUE(mask.pixels[i] == 0.0f || mask.pixels[i] == 1.0f);
    if (mask.pixels[i] == 0.0f) {
      EXPECT_EQ(distance.pixels[i], 0.0f);
      continue;
    }
    ++band;
    EXPECT_GE(distance.pixels[i], -1.42f);  // the band's inner end
    EXPECT_LE(distance.pixels[i], 2.83f);   // the band's outer end
  }
  // The ball's outline (~26 texels across) and the ground's four open edges: a band a few
  // texels wide, far from the whole map.
  EXPECT_GT(band, 200u);
  EXPECT_LT(band, mask.pixels.size() / 8);
  rig.set({"debug_outputs=false"});
  rig.render();
  for (const auto& p : rig.session().plan().passes) EXPECT_NE(p.name, "esm_debug");
}

// aa_width = 0 gives a binary mask (sub-texel edges, no ramp); the default ramp is one pixel.
TEST(EsmModes, ZeroRampWidthIsBinary) {
  test::EsmRig rig(192, 144, 256);
  rig.set_scene(*scene::make_builtin_scene("ball"));
  rig.use("esm");
  rig.set({"aa_width=0"});
  rig.render();
  EXPECT_EQ(count_between(rig.shadow_mask(), 0.0f, 1.0f), 0u);
}
