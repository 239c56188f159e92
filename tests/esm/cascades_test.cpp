// esm with cascaded shadow maps (scene/cascades.h): its depth pass and silhouette quads are drawn
// per cascade with that cascade's texel size, and the mask reads each receiver in the cascade the
// other techniques read it in. On `avenue` under a point-sized sun, four 1024^2 cascades give a
// smaller edge error against the exact hard shadow than one 2048^2 map (the same texels), as they
// do for plain shadow mapping (`hard`). Measured (llvmpipe), one map / four cascades: hard 0.0724 /
// 0.0469, esm 0.0342 / 0.0324 (0.0485 / 0.0338 before esm's band was made linear: its sub-texel
// edges gain less from smaller texels than the plain map's staircase does).
#include <gtest/gtest.h>

#include <cstdio>

#include "esm_rig.h"
#include "metrics/edge_error.h"
#include "scene/builtin_scenes.h"
#include "test_support/inspection.h"

using namespace penumbra;

TEST(EsmCascades, FourCascadesHaveASmallerEdgeErrorThanOneMap) {
  test::EsmRig rig(320, 180, 2048);
  scene::Scene s = *scene::make_builtin_scene("avenue");
  s.light.size = 0.0f;
  rig.set_scene(s);
  rig.use("hard");
  rig.render();  // the G-buffer every technique shares
  const metrics::MaskImage reference = test::exact_hard_reference(rig, s);
  const metrics::CoverageMask coverage = rig.coverage();
  double error[2][2] = {};  // [technique: hard, esm][one map, four cascades]
  for (int t = 0; t < 2; ++t)
    for (int c = 0; c < 2; ++c) {
      ASSERT_TRUE(rig.session().set_cascades({.count = c == 0 ? 1 : 4}));
      rig.use(t == 0 ? "hard" : "esm");
      rig.render();
      test::save_for_inspection(std::string("avenue_") + (t == 0 ? "hard" : "esm") + (c == 0 ? "_one" : "_four"),
                                rig.shadow_mask());
      Result<metrics::EdgeError> e = metrics::edge_error(rig.shadow_mask(), reference, coverage);
      ASSERT_TRUE(e);
      error[t][c] = e->error;
    }
  std::printf("[ measure  ] edge error, one 2048^2 map / four 1024^2 cascades: hard %.4f / %.4f, esm %.4f / %.4f\n",
              error[0][0], error[0][1], error[1][0], error[1][1]);
  EXPECT_LT(error[1][1], 0.95 * error[1][0]) << "esm: cascades nearer the exact edges";
  EXPECT_LT(error[0][1], 0.8 * error[0][0]) << "hard: cascades nearer the exact edges";
  EXPECT_LE(error[1][1], error[0][1]) << "esm no worse than plain shadow mapping with the same cascades";
}
