#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "raytraced_reference.h"
#include "scene/builtin_scenes.h"
#include "scene/load_scene.h"

using namespace penumbra;

TEST(BuiltinScenes, EveryBuiltinBuildsWithinBudgetAndIsSeenByItsCamera) {
  const auto names = scene::builtin_scene_names();
  ASSERT_EQ(names.size(), 8u);
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

// room: its lamp is a point light inside the room, so every shadow map holds six faces; the
// parameters move the lamp and size it, and a room the furniture cannot stand in (a zero-size
// one among them) or a lamp outside it is refused with the limit.
TEST(BuiltinScenes, TheRoomIsLitByALampInsideIt) {
  Result<scene::Scene> room = scene::make_builtin_scene("room");
  ASSERT_TRUE(room) << room.error().to_string();
  EXPECT_EQ(room->light.type, scene::LightType::point);
  EXPECT_TRUE(scene::shadow_frustum(room->light, room->bounds).six_faces);
  EXPECT_FLOAT_EQ(room->light.size, 0.25f);
  Result<scene::Scene> low = scene::make_builtin_scene("room", {{"lamp_height", 1.5f}, {"light_size", 0.5f}});
  ASSERT_TRUE(low);
  EXPECT_FLOAT_EQ(low->light.position.y, 1.5f);
  EXPECT_FLOAT_EQ(low->light.size, 0.5f);
  Result<scene::Scene> spot = scene::make_builtin_scene("room", {{"lamp_cone", 60.0f}});  // one map, to compare
  ASSERT_TRUE(spot);
  EXPECT_EQ(spot->light.type, scene::LightType::spot);
  EXPECT_FALSE(scene::shadow_frustum(spot->light, spot->bounds).six_faces);
  const std::pair<scene::ProceduralParams, const char*> bad[] = {
      {{{"room_width", 0.0f}}, "room_width 0 m is below the smallest room"},
      {{{"room_depth", 2.0f}}, "room_depth 2 m"},
      {{{"room_height", 0.0f}}, "room_height 0 m"},
      {{{"lamp_height", 3.0f}}, "outside the room"},
      {{{"lamp_height", 0.1f}}, "outside the room"},
      {{{"light_size", -1.0f}}, "outside [0, 1]"},
      {{{"lamp_cone", 95.0f}}, "lamp_cone: spot angle 95 degrees is outside [1, 89]"}};
  for (const auto& [params, expected] : bad) {
    Result<scene::Scene> s = scene::make_builtin_scene("room", params);
    ASSERT_FALSE(s) << expected;
    EXPECT_NE(s.error().to_string().find(expected), std::string::npos) << s.error().to_string();
    EXPECT_NE(s.error().to_string().find("scene room"), std::string::npos) << s.error().to_string();
  }
}

// avenue: a street long enough for cascades (casters from about 1 m to `length` ahead of the camera,
// inside the camera's far plane), under a directional light; lengths and spacings that cannot be
// built are refused with the limit.
TEST(BuiltinScenes, TheAvenueRunsFarAheadOfTheCamera) {
  Result<scene::Scene> avenue = scene::make_builtin_scene("avenue");
  ASSERT_TRUE(avenue) << avenue.error().to_string();
  EXPECT_EQ(avenue->light.type, scene::LightType::directional);
  const glm::vec3 forward = avenue->camera.forward();
  EXPECT_GT(glm::dot(avenue->bounds.min - avenue->camera.position, forward) +
                glm::dot(avenue->bounds.max - avenue->camera.position, forward), 150.0f);
  EXPECT_GE(avenue->camera.far_plane, 200.0f);
  Result<scene::Scene> short_one = scene::make_builtin_scene("avenue", {{"length", 40.0f}});
  ASSERT_TRUE(short_one);
  EXPECT_LT(short_one->bounds.extent().z, avenue->bounds.extent().z);
  const std::pair<scene::ProceduralParams, const char*> bad[] = {
      {{{"length", 5.0f}}, "length must be in [10, 2000]"},
      {{{"post_spacing", 0.0f}}, "post_spacing must be at least 1"},
      {{{"post_height", 0.0f}}, "post_height must be in [0.5, 50]"}};
  for (const auto& [params, expected] : bad) {
    Result<scene::Scene> s = scene::make_builtin_scene("avenue", params);
    ASSERT_FALSE(s) << expected;
    EXPECT_NE(s.error().to_string().find(expected), std::string::npos) << s.error().to_string();
  }
}

// load_scene (the CLI's --scene): a built-in's parameters after ':' as k=v,k=v; malformed or
// unknown ones are errors naming what is wrong.
TEST(BuiltinScenes, LoadSceneTakesParametersAfterAColon) {
  Result<scene::Scene> s = scene::load_scene("room:lamp_height=1.8,light_size=0.4");
  ASSERT_TRUE(s) << s.error().to_string();
  EXPECT_FLOAT_EQ(s->light.position.y, 1.8f);
  EXPECT_FLOAT_EQ(s->light.size, 0.4f);
  const std::pair<const char*, const char*> bad[] = {{"room:lamp_height", "is not k=v"},
                                                     {"room:lamp_height=high", "'high' for 'lamp_height'"},
                                                     {"room:lamp_height=1e99", "is not finite"},
                                                     {"room:", "is not k=v"},
                                                     {"room:colour=1", "unknown parameter 'colour'"},
                                                     {"hall:size=1", "neither a .gltf/.glb file nor a built-in"}};
  for (const auto& [text, expected] : bad) {
    Result<scene::Scene> r = scene::load_scene(text);
    ASSERT_FALSE(r) << text;
    EXPECT_NE(r.error().to_string().find(expected), std::string::npos) << text << ": " << r.error().to_string();
  }
}

