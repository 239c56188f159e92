#include <gtest/gtest.h>

#include "raytraced_reference.h"
#include "scene/builtin_scenes.h"
#include "scene/load_scene.h"

using namespace penumbra;

TEST(BuiltinScenes, EveryBuiltinBuildsWithinBudgetAndIsSeenByItsCamera) {
  const auto names = scene::builtin_scene_names();
  ASSERT_EQ(names.size(), 5u);
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
