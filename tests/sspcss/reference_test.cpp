// Error against the ray-traced reference (Embree: exact visibility of the emitter disk from the
// very G-buffer pixels the GPU rendered, 256 light samples per pixel), at sspcss's defaults on
// every built-in scene, next to hard shadows and PCF on the same frame: the technique's promise
// is a penumbra clearly closer to the truth than theirs.
//
// Size 480x270: sspcss works on screen pixels, so its error depends on how many pixels a
// penumbra covers. Measured penumbra RMSE (sspcss / pcf / hard), OSMesa, 2048^2 map:
//   size      ball                 fence                poles                colonnade            showcase
//   320x180   0.064/0.214/0.274    0.174/0.248/0.309    0.135/0.196/0.304    0.119/0.212/0.288    0.115/0.131/0.300
//   480x270   0.060/0.214/0.275    0.164/0.243/0.314    0.132/0.193/0.302    0.109/0.213/0.291    0.101/0.132/0.308
//   640x360   0.060/0.211/0.276    0.163/0.243/0.314    0.133/0.195/0.304    0.103/0.214/0.291    0.103/0.146/0.306
// At 320x180 the showcase's thin poles and pickets are a pixel wide and sspcss is only 12% under
// PCF there; from 480x270 on it is 24-72% under PCF on every scene.
#include <gtest/gtest.h>

#include <cstdio>
#include <ostream>

#include "sspcss_rig.h"

namespace penumbra::test {
namespace {

constexpr int kW = 480, kH = 270;

struct Case {
  const char* scene;
  double bound;  // sspcss penumbra RMSE: the measured value above + ~15%
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.scene; }

class SspcssReference : public ::testing::TestWithParam<Case> {};

TEST_P(SspcssReference, PenumbraCloserToTheReferenceThanHardAndPcf) {
  const Case c = GetParam();
  BaselineRenderer r;
  const scene::Scene s = builtin_scene(c.scene);
  RenderedFrame f = r.render(s, "sspcss", {}, kW, kH);
  const metrics::MaskImage ref = traced_reference(s, f);
  save_for_inspection(std::string(c.scene) + "_sspcss", f.mask);
  save_for_inspection(std::string(c.scene) + "_reference", ref);
  const double sspcss = penumbra_rmse(f.mask, ref, f.coverage);
  const double pcf = penumbra_rmse(r.render(s, "pcf", {}, kW, kH).mask, ref, f.coverage);
  const double hard = penumbra_rmse(r.render(s, "hard", {}, kW, kH).mask, ref, f.coverage);
  std::printf("[ measure  ] %s %dx%d penumbra RMSE: sspcss %.4f, pcf %.4f, hard %.4f\n", c.scene, kW, kH, sspcss,
              pcf, hard);
  EXPECT_LT(sspcss, c.bound) << c.scene;
  // "Clearly below": at most 85% of the better of the two (measured: at most 76%, showcase).
  EXPECT_LT(sspcss, 0.85 * std::min(pcf, hard)) << c.scene;
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, SspcssReference,
                         ::testing::Values(Case{"ball", 0.070}, Case{"fence", 0.19}, Case{"poles", 0.152},
                                           Case{"colonnade", 0.125}, Case{"showcase", 0.116}),
                         [](const auto& info) { return std::string(info.param.scene); });

}  // namespace
}  // namespace penumbra::test
