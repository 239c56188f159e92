// Error against the ray-traced reference (Embree: exact visibility of the emitter disk from the
// very G-buffer pixels the GPU rendered, 256 light samples per pixel), at sspcss's defaults on
// every built-in scene, next to hard shadows and PCF on the same frame: the technique's promise
// is a penumbra clearly closer to the truth than theirs.
//
// Size 480x270: sspcss works on screen pixels, so its error depends on how many pixels a
// penumbra covers. Measured penumbra RMSE (the soft penumbra of the frame's pixel classes, as
// `penumbra eval` reports it; sspcss / pcf / hard), OSMesa, 2048^2 map:
//   size      ball                 fence                poles                colonnade            showcase
//   320x180   0.030/0.210/0.275    0.055/0.197/0.278    0.044/0.202/0.313    0.077/0.206/0.288    0.087/0.097/0.299
//   480x270   0.023/0.213/0.277    0.042/0.194/0.285    0.043/0.187/0.285    0.055/0.207/0.293    0.072/0.108/0.299
//   640x360   0.022/0.211/0.276    0.039/0.194/0.285    0.031/0.182/0.304    0.050/0.207/0.293    0.069/0.118/0.297
// At 320x180 the showcase's thin poles and pickets are a pixel wide and sspcss is only 10% under
// PCF there; from 480x270 on it is 33-89% under PCF on every scene.
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
  const double sspcss = penumbra_rmse(f.mask, ref, f);
  const double pcf = penumbra_rmse(r.render(s, "pcf", {}, kW, kH).mask, ref, f);
  const double hard = penumbra_rmse(r.render(s, "hard", {}, kW, kH).mask, ref, f);
  std::printf("[ measure  ] %s %dx%d penumbra RMSE: sspcss %.4f, pcf %.4f, hard %.4f\n", c.scene, kW, kH, sspcss,
              pcf, hard);
  EXPECT_LT(sspcss, c.bound) << c.scene;
  // "Clearly below": at most 85% of the better of the two (measured: at most 67%, showcase).
  EXPECT_LT(sspcss, 0.85 * std::min(pcf, hard)) << c.scene;
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, SspcssReference,
                         ::testing::Values(Case{"ball", 0.027}, Case{"fence", 0.049}, Case{"poles", 0.050},
                                           Case{"colonnade", 0.064}, Case{"showcase", 0.083}),
                         [](const auto& info) { return std::string(info.param.scene); });

}  // namespace
}  // namespace penumbra::test
