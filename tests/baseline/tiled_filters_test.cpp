// The shared tile classifier (passes/shadow_tiles) under pcf and pcss: with tiles on, a filter's
// mask is its untiled mask (the classifier only skips work whose answer it knows), the classifier
// never calls a tile with reference penumbra in it lit or umbra, it skips a real share of the tiles,
// a scene without a caster gives an all-lit mask with (almost) every tile skipped, and the planes
// it classifies with bound the shadow map.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "baseline_frame.h"
#include "techniques/builtin_techniques.h"
#include "raytraced_reference.h"
#include "scene/builtin_scenes.h"
#include "test_support/inspection.h"

namespace penumbra::test {
namespace {

constexpr int kW = 192, kH = 144;

// Tile classes as the R8 texture holds them (tile_class.glsl): 0 umbra, 128/255 penumbra, 1 lit.
enum class TileClass { umbra, penumbra, lit };
TileClass tile_class_of(float texel) {
  return texel < 0.25f ? TileClass::umbra : texel > 0.75f ? TileClass::lit : TileClass::penumbra;
}

struct Variant {
  std::string technique;
  std::vector<std::string> settings;
  int tile = 16;
  double min_skipped_share = 0.1;  // of the tiles, on every built-in scene
};

const std::vector<Variant> kVariants = {
    {"pcss", {}},
    {"pcss", {"tile_size=8"}, 8},
    // Wide penumbrae: a reach of a fifth of the map sees a caster from almost every tile of showcase.
    {"pcss", {"light_size_scale=3", "max_search_uv=0.2", "max_filter_uv=0.2"}, 16, 0.02},
    {"pcf", {}},
    {"pcf", {"kernel=vogel", "radius=12"}},
};

std::string describe(const Variant& v) {
  std::string s = v.technique;
  for (const std::string& k : v.settings) s += " " + k;
  return s;
}

float max_difference(const metrics::MaskImage& a, const metrics::MaskImage& b) {
  float d = 0.0f;
  for (size_t i = 0; i < a.pixels.size(); ++i) d = std::max(d, std::abs(a.pixels[i] - b.pixels[i]));
  return d;
}

TEST(TiledFilters, MaskEqualsTheUntiledMaskOnEveryBuiltinScene) {
  TechniqueRig rig({.width = kW, .height = kH, .shadow_size = 1024, .techniques = register_builtin_techniques});
  for (const std::string& name : scene::builtin_scene_names()) {
    const scene::Scene s = builtin_scene(name);
    for (const Variant& v : kVariants) {
      SCOPED_TRACE(describe(v) + " on " + name);
      std::vector<std::string> on = v.settings, off = v.settings;
      on.push_back("tiles=true");
      off.push_back("tiles=false");
      RenderedFrame untiled = rig.render_frame(s, v.technique, off);
      RenderedFrame tiled = rig.render_frame(s, v.technique, on);
      ASSERT_EQ(tiled.mask.pixels.size(), untiled.mask.pixels.size());
      EXPECT_LE(max_difference(tiled.mask, untiled.mask), 1.0f / 255.0f);
      // Not equal because nothing was skipped: every scene has lit or umbra tiles the filter never
      // ran on, but a room lit from inside (six faces), whose lit tiles the classifier leaves to
      // the filters.
      const metrics::MaskImage classes = rig.read("tile_class");
      ASSERT_EQ(classes.width, (kW + v.tile - 1) / v.tile);
      ASSERT_EQ(classes.height, (kH + v.tile - 1) / v.tile);
      size_t lit = 0, skipped = 0;
      for (float c : classes.pixels) {
        lit += tile_class_of(c) == TileClass::lit;
        skipped += tile_class_of(c) != TileClass::penumbra;
      }
      if (scene::shadow_frustum(s.light, s.bounds).six_faces)
        EXPECT_EQ(lit, 0u) << "six faces: every tile with a receiver is penumbra";
      else if (name == "avenue")  // shadows of posts, slats and benches reach nearly every tile of the
        EXPECT_GT(skipped, 0u);   // street, under a pergola that hides the sky: 6 or 7 of 540 skipped
      else
        EXPECT_GT(double(skipped), v.min_skipped_share * double(classes.pixels.size()))
            << "tiles classified lit or umbra: " << skipped << " of " << classes.pixels.size();
    }
  }
}

// Pixels whose exact visibility is strictly inside (eps, 1 - eps) are penumbra whatever the
// technique: none may sit in a tile the classifier skipped.
TEST(TiledFilters, NoReferencePenumbraPixelInALitOrUmbraTile) {
  constexpr float kEps = 0.02f;
  TechniqueRig rig({.width = kW, .height = kH, .shadow_size = 2048, .techniques = register_builtin_techniques});
  for (const std::string& name : scene::builtin_scene_names()) {
    SCOPED_TRACE(name);
    const scene::Scene s = builtin_scene(name);
    Result<reference::RayScene> rs = reference::RayScene::build(s);
    ASSERT_TRUE(rs) << rs.error().message;
    RenderedFrame f = rig.render_frame(s, "pcss", {"tiles=true"});
    const metrics::MaskImage ref =
        reference::trace_visibility(*rs, s.light, f.positions, f.normals, kW, kH, {.samples = 128}, f.coverage);
    const metrics::MaskImage classes = rig.read("tile_class");
    size_t penumbra_pixels = 0, misclassified = 0, skipped_tiles = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const float v = ref.pixels[size_t(y) * kW + x];
        if (!f.coverage[size_t(y) * kW + x] || v <= kEps || v >= 1.0f - kEps) continue;
        ++penumbra_pixels;
        misclassified += tile_class_of(classes.pixels[size_t(y / 16) * classes.width + x / 16]) != TileClass::penumbra;
      }
    for (float c : classes.pixels) skipped_tiles += tile_class_of(c) != TileClass::penumbra;
    EXPECT_GT(penumbra_pixels, 0u);
    EXPECT_EQ(misclassified, 0u) << "of " << penumbra_pixels << " reference penumbra pixels";
    if (scene::shadow_frustum(s.light, s.bounds).six_faces)  // the room: nothing skipped (above)
      EXPECT_EQ(skipped_tiles, 0u);
    else
      EXPECT_GT(skipped_tiles, 0u);
    save_for_inspection("tiles_" + name + "_class", classes);
  }
}

TEST(TiledFilters, SceneWithoutCasterIsAllLitAndAlmostNoTileFiltered) {
  scene::Scene s = builtin_scene("ball");
  // Keep only the ground: nothing casts a shadow.
  std::erase_if(s.instances, [&](const scene::Instance& i) { return s.meshes[i.mesh].name != "ground"; });
  ASSERT_EQ(s.instances.size(), 1u);
  TechniqueRig rig({.width = kW, .height = kH, .shadow_size = 1024, .techniques = register_builtin_techniques});
  for (const std::string t : {"pcf", "pcss"}) {
    SCOPED_TRACE(t);
    RenderedFrame f = rig.render_frame(s, t, {"tiles=true"});
    for (size_t i = 0; i < f.mask.pixels.size(); ++i) ASSERT_EQ(f.mask.pixels[i], 1.0f) << "pixel " << i;
    // Every tile lit but those whose receivers' taps reach past the far edge of what the light
    // sees with a reference beyond the far plane (the ground's far edge here): there cleared
    // texels count as blockers (depth 1 < reference), so the classifier cannot call them lit.
    size_t lit = 0;
    const metrics::MaskImage classes = rig.read("tile_class");
    for (float c : classes.pixels) {
      ASSERT_NE(tile_class_of(c), TileClass::umbra);
      lit += tile_class_of(c) == TileClass::lit;
    }
    EXPECT_GE(lit, classes.pixels.size() * 9 / 10) << lit << " of " << classes.pixels.size() << " tiles lit";
  }
}

// The classifier's picture of the map (shadow_planes.comp.glsl): per block a plane and the range
// of the residuals about it. The range must hold every drawn texel of the block, cleared texels
// must mark it, and where the light sees one flat surface the fitted plane must be that surface
// (a range near zero). 1020 texels: blocks of 9 rows, more than the invocations sharing a block.
TEST(ShadowPlanes, ResidualRangeHoldsEveryDrawnTexelOfItsBlock) {
  for (const int map : {1024, 1020}) {
    TechniqueRig rig({.width = kW, .height = kH, .shadow_size = map, .techniques = register_builtin_techniques,
                      .keep_alive = {"shadow_map", "shadow_planes"}});
    for (const std::string name : {"ball", "colonnade", "showcase"}) {
      SCOPED_TRACE(name + " at " + std::to_string(map));
      rig.render_frame(builtin_scene(name), "pcss", {"tiles=true"});
      const metrics::MaskImage depth = rig.read("shadow_map");
      std::vector<metrics::MaskImage> plane;
      for (int c = 0; c < 4; ++c) plane.push_back(rig.read("shadow_planes", c));
      ASSERT_EQ(depth.width, map);
      const int blocks = plane[0].width, block = (map + blocks - 1) / blocks;
      // Read-back rows run top to bottom; the shader's texel rows bottom to top.
      auto at = [](const metrics::MaskImage& m, int x, int gl_y) { return m.pixels[size_t(m.height - 1 - gl_y) * m.width + x]; };
      size_t drawn_blocks = 0, flat_blocks = 0, outside = 0;
      for (int by = 0; by < blocks; ++by)
        for (int bx = 0; bx < blocks; ++bx) {
          // The shader's blocks: those past the map's edge (127 x 9 > 1020) repeat its last texels.
          const glm::ivec2 first = glm::min(glm::ivec2(bx, by) * block, glm::ivec2(map - 1));
          const glm::ivec2 last = glm::min(first + block, glm::ivec2(map));
          const glm::vec2 centre = 0.5f * glm::vec2(first + last);
          const glm::vec2 slope = glm::vec2(at(plane[0], bx, by), at(plane[1], bx, by)) / float(map);
          const float lo = at(plane[2], bx, by), hi = at(plane[3], bx, by);
          bool cleared = false;
          for (int y = first.y; y < last.y; ++y)
            for (int x = first.x; x < last.x; ++x) {
              const float d = at(depth, x, y);
              if (d >= 1.0f) {
                cleared = true;
                continue;
              }
              const float residual = d - glm::dot(glm::vec2(x, y) + 0.5f - centre, slope);
              outside += residual < lo - 1e-6f || (hi < 1e29f && residual > hi + 1e-6f);
            }
          EXPECT_EQ(cleared, hi >= 1e29f) << "block " << bx << ", " << by;
          if (cleared) continue;
          ++drawn_blocks;
          flat_blocks += hi - lo < 1e-6f;
        }
      EXPECT_EQ(outside, 0u) << "drawn texels outside their block's residual range";
      // The ground fills most of what the light sees; casters' outlines widen a few blocks' range.
      EXPECT_GT(drawn_blocks, 0u);
      EXPECT_GT(double(flat_blocks), 0.5 * double(drawn_blocks)) << flat_blocks << " of " << drawn_blocks;
    }
  }
}

}  // namespace
}  // namespace penumbra::test
