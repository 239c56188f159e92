// Two crossed pipes casting shadows on a wall (Bujnak, Figures 9-11): where the silhouettes
// cross, the quads of one pipe's edges lie over the other pipe's shadow. No crack (a lit line
// along an edge inside the union of the shadows) and no lit hole may appear there, whether the
// pipes intersect or pass each other at different depths, at low and higher resolution, with
// MAX blending or the two-pass fallback.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "esm_rig.h"
#include "esm_scenes.h"
#include "metrics/edge_error.h"
#include "raytraced_reference.h"

using namespace penumbra;

namespace {

constexpr int kSize = 256;

// The exact hard shadow of one of the two pipes alone (the other cylinder's triangles removed).
metrics::MaskImage single_pipe_shadow(test::TechniqueRig& rig, scene::Scene s, bool first) {
  scene::Mesh& pipes = s.meshes[1];
  const size_t half = pipes.indices.size() / 2;  // add_cylinder twice: the first half is pipe 1
  if (first) pipes.indices.resize(half);
  else pipes.indices.erase(pipes.indices.begin(), pipes.indices.begin() + static_cast<std::ptrdiff_t>(half));
  return test::exact_hard_reference(rig, s, 1);
}

struct Crossing {
  size_t pixels = 0;       // receivers near the crossing
  size_t shadowed = 0;     // of which in the reference's shadow, 2 px or more from its edges
  float worst_lit = 0.0f;  // the brightest esm value among those (a hole or crack if large)
  float worst_dark = 1.0f; // the darkest esm value in the reference's light, a texel or more from its edges
};

// Wall pixels within 12 px of places where both single-pipe shadows have an edge (the crossing). A
// crack or hole lies inside the union of the shadows, along an edge of one pipe's shadow that
// crosses the other's: 2 px from the union's own edges is inside. Near a reflex corner of the
// union one texel holds one distance, so its corner is filled by up to a texel (the paper's
// "only one silhouette edge per fragment"): the lit side is checked a texel away.
Crossing examine(const metrics::MaskImage& esm, const metrics::MaskImage& reference, const metrics::MaskImage& a,
                 const metrics::MaskImage& b, const metrics::CoverageMask& coverage, float texel_px) {
  const metrics::CoverageMask near_a = metrics::edge_band(a, coverage, 12.0f);
  const metrics::CoverageMask near_b = metrics::edge_band(b, coverage, 12.0f);
  const metrics::CoverageMask union_edges = metrics::edge_band(reference, coverage, 2.0f);
  const metrics::CoverageMask union_texel = metrics::edge_band(reference, coverage, 2.0f + 1.2f * texel_px);
  Crossing c;
  for (size_t i = 0; i < esm.pixels.size(); ++i) {
    if (!coverage[i] || !near_a[i] || !near_b[i]) continue;
    ++c.pixels;
    if (reference.pixels[i] < 0.5f && !union_edges[i]) {
      ++c.shadowed;
      c.worst_lit = std::max(c.worst_lit, esm.pixels[i]);
    } else if (reference.pixels[i] >= 0.5f && !union_texel[i]) {
      c.worst_dark = std::min(c.worst_dark, esm.pixels[i]);
    }
  }
  return c;
}

}  // namespace

TEST(EsmCrossedPipes, NoCracksOrLitHolesWhereSilhouettesCross) {
  for (const float gap : {0.0f, 0.3f}) {
    const scene::Scene s = test::crossed_pipes(0.12f, gap);
    test::EsmRig rig(kSize, kSize, 128);
    rig.set_scene(s);
    rig.use("esm");
    rig.render();
    // Receivers: the wall (z = 0), where the paper's figures look; not the pipes themselves.
    metrics::CoverageMask coverage = rig.coverage();
    const std::vector<glm::vec4> world = rig.positions();
    for (size_t i = 0; i < coverage.size(); ++i) coverage[i] = coverage[i] && std::abs(world[i].z) < 0.01f;
    const metrics::MaskImage reference = test::exact_hard_reference(rig, s, 1);
    const metrics::MaskImage a = single_pipe_shadow(rig, s, true), b = single_pipe_shadow(rig, s, false);
    for (const int map : {128, 256}) {
      for (const char* resolve : {"max_blend", "two_pass"}) {
        rig.set_shadow_size(map);
        rig.set({std::string("overlap_resolve=") + resolve});
        rig.render();
        const metrics::MaskImage esm = rig.shadow_mask();
        // A wall texel seen by the camera: 6.6 cm at 128^2 (spot 35 degrees, 6 m away), 1.45 cm a pixel.
        const float texel_px = 4.5f * 128.0f / static_cast<float>(map);
        const Crossing c = examine(esm, reference, a, b, coverage, texel_px);
        std::printf("[ measure  ] gap %.1f, %d^2, %s: %zu crossing pixels (%zu shadowed), brightest in shadow %.3f, "
                    "darkest in light %.3f\n", gap, map, resolve, c.pixels, c.shadowed, c.worst_lit, c.worst_dark);
        EXPECT_GT(c.shadowed, 200u) << "the crossing must be in view";
        EXPECT_LE(c.worst_lit, 0.05f) << "lit hole or crack: gap " << gap << ", " << map << "^2, " << resolve;
        EXPECT_GE(c.worst_dark, 0.95f) << "dark blot: gap " << gap << ", " << map << "^2, " << resolve;
        test::save_for_inspection("pipes_" + std::to_string(map) + "_" + resolve + "_" + std::to_string(int(gap * 10)), esm);
      }
    }
  }
}
