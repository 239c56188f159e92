#pragma once
// A rendered frame against the truth: the ray-traced reference (Embree, techniques/reference) of
// the frame's own G-buffer, and the penumbra RMSE of any mask against it (the measure of
// `penumbra eval`'s "RMSE penumbra" column: the soft penumbra of the frame's pixel classes). With the built-in
// techniques registered beside a plugin, a plugin's test states "nearer the truth than PCF":
//
//   TechniqueRig rig({.techniques = penumbra::register_builtin_techniques,  // Penumbra::techniques
//                     .plugin_dirs = {MY_PLUGIN_DIR}});
//   const scene::Scene s = builtin_scene("ball");
//   RenderedFrame mine = rig.render_frame(s, "msm"), pcf = rig.render_frame(s, "pcf");
//   metrics::MaskImage truth = traced_reference(s, mine);
//   EXPECT_LT(penumbra_rmse(mine.mask, truth, mine), penumbra_rmse(pcf.mask, truth, mine));
#include "metrics/mask_image.h"
#include "metrics/mask_metrics.h"
#include "scene/scene.h"
#include "test_support/technique_rig.h"

namespace penumbra::test {

// Exact area-light visibility of the scene's light (`samples` stratified light points) at the
// frame's receivers; 1 off them. Rows top to bottom, like the frame's mask.
metrics::MaskImage traced_reference(const scene::Scene& scene, const RenderedFrame& frame, int samples = 256);

// Every error of `mask` against `reference` (metrics::compare_masks) over the pixel classes of
// `frame`, the frame both masks are of, so rmse_penumbra is `penumbra eval`'s. Fails the test and
// returns zeros on error or when the frame's geometry and the reference differ in size.
metrics::MaskErrors frame_errors(const metrics::MaskImage& mask, const metrics::MaskImage& reference,
                                 const RenderedFrame& frame);

// Penumbra RMSE of `mask` against `reference` over the soft penumbra (metrics/pixel_classes.h:
// the reference strictly between lit and umbra, away from the geometric edges of `frame`, the
// frame both masks are of). Fails the test and returns 1 on error or when the frame has no soft
// penumbra to judge.
double penumbra_rmse(const metrics::MaskImage& mask, const metrics::MaskImage& reference, const RenderedFrame& frame);

}  // namespace penumbra::test
