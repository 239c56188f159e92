// mpg's tiles (tiles=true, the default), both exact: the dilation takes no taps in tiles out of
// its reach of a tile with D > 0 (d_tiles), and blur passes after the first run over the tiles
// with D > 0 into the texture of the version two back (a ping-pong output). The mask must be the
// untiled one bit for bit; the list must leave tiles out (else nothing is saved) and keep every
// tile some pass changes (else the mask would differ).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "exec/tile_list_readback.h"
#include "mpg_rig.h"
#include "mpg_settings.h"

using namespace penumbra;

namespace {

// The defaults, few passes, no dilation (D > 0 in shadows only), a fixed wide kernel, the early-out.
const std::vector<std::vector<std::string>> kVariants = {
    {}, {"max_passes=3"}, {"dilation=false"}, {"kernel_mode=fixed", "max_kernel=29"}, {"umbra_early_out=true"}};

std::string describe(const std::vector<std::string>& settings) {
  std::string s = "mpg";
  for (const std::string& k : settings) s += " " + k;
  return s;
}

metrics::MaskImage render(test::MpgRig& rig, std::vector<std::string> settings, bool tiles) {
  settings.push_back(tiles ? "tiles=true" : "tiles=false");
  rig.set(settings);
  rig.render();
  return rig.shadow_mask();
}

}  // namespace

TEST(MpgTiledBlur, MaskIsTheUntiledMaskOnEveryBuiltinScene) {
  test::MpgRig rig(test::kWidth, test::kHeight, test::kShadowSize);
  for (const std::string& name : scene::builtin_scene_names()) {
    rig.set_scene(test::make_scene(name));
    for (const auto& v : kVariants) {
      SCOPED_TRACE(describe(v) + " on " + name);
      const metrics::MaskImage untiled = render(rig, v, false);
      const metrics::MaskImage tiled = render(rig, v, true);
      // Passes per tile (0: not listed), as blur_tiles wrote them for this frame.
      const metrics::MaskImage passes = rig.read("blur_tile_passes");
      ASSERT_EQ(passes.width, (test::kWidth + 15) / 16);
      ASSERT_EQ(passes.height, (test::kHeight + 15) / 16);
      ASSERT_EQ(tiled.pixels.size(), untiled.pixels.size());
      size_t differing = 0;
      for (size_t i = 0; i < tiled.pixels.size(); ++i) differing += tiled.pixels[i] != untiled.pixels[i];
      EXPECT_EQ(differing, 0u) << "of " << tiled.pixels.size() << " pixels";
      size_t listed = 0, short_lived = 0;
      for (float m : passes.pixels) {
        EXPECT_EQ(m, std::floor(m));
        listed += m > 0.0f;
        short_lived += m > 0.0f && m < 10.0f;
      }
      EXPECT_GT(listed, 0u);
      EXPECT_LT(listed, passes.pixels.size()) << "every tile listed: the tiles save nothing here";
      if (v.empty()) {
        EXPECT_GT(short_lived, 0u) << "no listed tile skips a pass";
        // The first blur pass runs over every pixel, the others over the listed tiles (what
        // bench's traffic counts).
        const exec::Executor& executor = rig.session().executor();
        for (const graph::PlannedPass& p : executor.plan().passes) {
          if (p.name.rfind("multipass_blur[", 0) != 0) continue;
          const std::optional<exec::TileListCount> count = exec::dispatched_tiles(executor, p);
          if (p.iteration == 0) {
            EXPECT_FALSE(count.has_value()) << p.name;
          } else {
            ASSERT_TRUE(count.has_value()) << p.name;
            EXPECT_EQ(count->dispatched, listed) << p.name;
          }
        }
      }
    }
  }
}

// The dilation's skip: at 640x360 colonnade has tiles farther than the x pass's reach (3 tiles at
// dilation_kernel 29) from any tile with D > 0 (d_tiles), and farther than the y pass's from any
// tile with a non-zero row maximum (a_tiles), where those passes take no taps; the mask is still
// the untiled one.
TEST(MpgTiledBlur, DilationSkipsTilesOutOfReachOfDAndKeepsTheMask) {
  constexpr int kW = 640, kH = 360;
  test::MpgRig rig(kW, kH, test::kShadowSize);
  rig.set_scene(test::make_scene("colonnade"));
  const metrics::MaskImage untiled = render(rig, {}, false);
  const metrics::MaskImage tiled = render(rig, {}, true);
  const metrics::MaskImage d_marks = rig.read("d_tiles"), a_marks = rig.read("a_tiles");
  for (const metrics::MaskImage* m : {&d_marks, &a_marks}) {
    ASSERT_EQ(m->width, (kW + 15) / 16);
    ASSERT_EQ(m->height, (kH + 15) / 16);
  }
  auto far_from = [](const metrics::MaskImage& marks, int tx, int ty, int reach) {
    for (int y = std::max(0, ty - reach); y <= std::min(marks.height - 1, ty + reach); ++y)
      for (int x = std::max(0, tx - reach); x <= std::min(marks.width - 1, tx + reach); ++x)
        if (marks.pixels[size_t(y) * marks.width + x] > 0.0f) return false;
    return true;
  };
  size_t with_d = 0, with_a = 0, skipped_x = 0, skipped_y = 0;
  for (int ty = 0; ty < d_marks.height; ++ty)
    for (int tx = 0; tx < d_marks.width; ++tx) {
      const size_t i = size_t(ty) * d_marks.width + tx;
      with_d += d_marks.pixels[i] > 0.0f;
      with_a += a_marks.pixels[i] > 0.0f;
      // The row maxima spread D along rows: a tile with one is near a tile with D > 0.
      if (a_marks.pixels[i] > 0.0f) {
        EXPECT_FALSE(far_from(d_marks, tx, ty, 3)) << tx << ", " << ty;
      }
      skipped_x += far_from(d_marks, tx, ty, 3);
      skipped_y += far_from(a_marks, tx, ty, 3);
    }
  EXPECT_GT(with_d, 0u);
  EXPECT_GE(with_a, with_d);
  EXPECT_GT(skipped_x, 0u);
  EXPECT_GT(skipped_y, 0u);
  size_t differing = 0;
  for (size_t i = 0; i < tiled.pixels.size(); ++i) differing += tiled.pixels[i] != untiled.pixels[i];
  EXPECT_EQ(differing, 0u) << "of " << tiled.pixels.size() << " pixels";
}

// Nothing casts a shadow: D = 0 everywhere, no tile is listed, and the mask is all lit.
TEST(MpgTiledBlur, SceneWithoutCasterListsNoTile) {
  scene::Scene s = test::make_scene("ball");
  std::erase_if(s.instances, [&](const scene::Instance& i) { return s.meshes[i.mesh].name != "ground"; });
  ASSERT_EQ(s.instances.size(), 1u);
  test::MpgRig rig(test::kWidth, test::kHeight, test::kShadowSize);
  rig.set_scene(s);
  const metrics::MaskImage mask = render(rig, {}, true);
  for (size_t i = 0; i < mask.pixels.size(); ++i) ASSERT_EQ(mask.pixels[i], 1.0f) << "pixel " << i;
  for (float m : rig.read("blur_tile_passes").pixels) ASSERT_EQ(m, 0.0f);
  for (float f : rig.read("d_tiles").pixels) ASSERT_EQ(f, 0.0f);
  for (float f : rig.read("a_tiles").pixels) ASSERT_EQ(f, 0.0f);
}
