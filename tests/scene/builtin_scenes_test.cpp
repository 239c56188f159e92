#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "raytraced_reference.h"
#include "scene/builtin_scenes.h"
#include "scene/load_scene.h"

using namespace penumbra;

TEST(BuiltinScenes, EveryBuiltinBuildsWithinBudgetAndIsSeenByItsCamera) {
  const auto names = scene::builtin_scene_names();
  ASSERT_EQ(names.size(), 6u);
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    Result<scene::Scene> s = scene::make_builtin_scene(name);
    ASSERT_TRUE(s) << s.error().to_string();
    EXPECT_FALSE(s->bounds.empty());
    EXPECT_GT(s->bounds.radius(), 1.0f);
    EXPECT_GT(s->triangle_count(), 10u);
    EXPECT_LT(s->triangle_count(), 60000u);
    for (const scene::Mesh& m : s->meshes) {
      EXPECT_EQ(m.indices.size() % 3, 0u);
      for (uint32_t i : m.indices) ASSERT_LT(i, m.vertices.size());
      EXPECT_LT(m.material, s->materials.size());
    }
    // The default camera sees the scene: most pixels hit geometry, and the default light casts
    // visible shadows with penumbrae onto what it sees.
    Result<reference::RayScene> rs = reference::RayScene::build(*s);
    ASSERT_TRUE(rs);
    reference::GBuffer g = reference::primary_gbuffer(*rs, s->camera, 48, 48);
    size_t covered = 0;
    for (uint8_t c : g.coverage) covered += c;
    EXPECT_GT(covered, g.coverage.size() / 2);
    metrics::MaskImage vis = reference::trace_visibility(*rs, s->light, g, {.samples = 16});
    size_t dark = 0, partial = 0;
    for (size_t i = 0; i < vis.pixels.size(); ++i) {
      if (!g.coverage[i]) continue;
      dark += vis.pixels[i] < 0.5f;
      partial += vis.pixels[i] > 0.05f && vis.pixels[i] < 0.95f;
    }
    EXPECT_GT(dark, 20u);
    EXPECT_GT(partial, 5u);
  }
}

TEST(BuiltinScenes, UnknownNameListsValidNames) {
  Result<scene::Scene> s = scene::make_builtin_scene("sponza");
  ASSERT_FALSE(s);
  const std::string msg = s.error().to_string();
  EXPECT_NE(msg.find("sponza"), std::string::npos);
  for (const std::string& name : scene::builtin_scene_names()) EXPECT_NE(msg.find(name), std::string::npos) << msg;
  Result<scene::Scene> viaload = scene::load_scene("sponza");
  ASSERT_FALSE(viaload);
  EXPECT_NE(viaload.error().message.find("showcase"), std::string::npos);
}

TEST(BuiltinScenes, ParametersChangeGeometryAndUnknownKeysAreRejected) {
  Result<scene::Scene> low = scene::make_builtin_scene("ball", {{"ball_height", 0.2f}});
  Result<scene::Scene> high = scene::make_builtin_scene("ball", {{"ball_height", 2.0f}});
  ASSERT_TRUE(low && high);
  EXPECT_NEAR(high->bounds.max.y - low->bounds.max.y, 1.8f, 1e-3f);
  Result<scene::Scene> bad = scene::make_builtin_scene("ball", {{"ball_heigth", 1.0f}});
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("ball_height"), std::string::npos);  // lists valid keys
}

// The palms' fronds are alpha-masked quads (Cherry & Kooima's Pool scene): light must pass
// through the gaps between the leaflets. The frond texture has holes and opaque texels, and rays
// straight down through the tallest crown are blocked clearly less often than when the same
// fronds are made opaque.
TEST(BuiltinScenes, PalmFrondsAreAlphaMaskedQuads) {
  Result<scene::Scene> s = scene::make_builtin_scene("palms");
  ASSERT_TRUE(s) << s.error().to_string();
  scene::Material* frond = nullptr;
  for (scene::Material& m : s->materials)
    if (m.name == "palm_frond") frond = &m;
  ASSERT_NE(frond, nullptr);
  EXPECT_EQ(frond->alpha_mode, scene::AlphaMode::mask);
  ASSERT_GE(frond->base_color_texture, 0);
  const scene::Image& img = s->images[static_cast<size_t>(frond->base_color_texture)];
  size_t holes = 0, opaque = 0;
  for (size_t i = 3; i < img.pixels.size(); i += 4) (img.pixels[i] < 128 ? holes : opaque) += 1;
  EXPECT_GT(holes, img.pixels.size() / 16);   // gaps and the outside of the outline
  EXPECT_GT(opaque, img.pixels.size() / 16);  // midrib and leaflets
  auto blocked_by_crown = [](const scene::Scene& scene) {
    Result<reference::RayScene> rs = reference::RayScene::build(scene);
    EXPECT_TRUE(rs);
    int blocked = 0;
    const glm::vec3 top(-2.18f, 5.0f, -1.41f);  // above the crown: base (-1.6, -1.2) leaning 10 degrees towards 200
    for (int i = 0; i < 400; ++i) {
      const float a = 0.0157f * static_cast<float>(i), r = 0.3f + 1.0f * static_cast<float>(i % 20) / 20.0f;
      const glm::vec3 o = top + glm::vec3(r * std::cos(a), 0.0f, r * std::sin(a));
      reference::RayHit hit;
      if (rs && rs->intersect(o, {0, -1, 0}, hit, 0.0f, 10.0f) && o.y - hit.t > 2.5f) ++blocked;  // a frond
    }
    return blocked;
  };
  const int masked = blocked_by_crown(*s);
  frond->alpha_mode = scene::AlphaMode::opaque;
  const int solid = blocked_by_crown(*s);
  std::printf("[ measure  ] rays blocked by the crown: %d masked, %d opaque (of 400)\n", masked, solid);
  EXPECT_GT(masked, 40);
  EXPECT_LT(masked + 40, solid);
}
