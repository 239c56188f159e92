#include "test_support/reference_comparison.h"

#include <gtest/gtest.h>

#include "raytraced_reference.h"

namespace penumbra::test {

metrics::MaskImage traced_reference(const scene::Scene& scene, const RenderedFrame& frame, int samples) {
  Result<reference::RayScene> rs = reference::RayScene::build(scene);
  EXPECT_TRUE(rs) << (rs ? "" : rs.error().to_string());
  if (!rs) return {};
  return reference::trace_visibility(*rs, scene.light, frame.positions, frame.normals, frame.mask.width,
                                     frame.mask.height, {.samples = samples}, frame.coverage);
}

metrics::MaskErrors frame_errors(const metrics::MaskImage& mask, const metrics::MaskImage& reference,
                                 const RenderedFrame& frame) {
  const metrics::PixelClasses classes = metrics::classify_pixels(reference, frame.coverage, &frame.geometry);
  if (classes.classes.empty()) {
    ADD_FAILURE() << "the reference and the frame's coverage or geometry differ in size";
    return {};
  }
  Result<metrics::MaskErrors> e = metrics::compare_masks(mask, reference, frame.coverage, classes);
  EXPECT_TRUE(e) << (e ? "" : e.error().to_string());
  return e ? *e : metrics::MaskErrors{};
}

double penumbra_rmse(const metrics::MaskImage& mask, const metrics::MaskImage& reference, const RenderedFrame& frame) {
  const metrics::MaskErrors e = frame_errors(mask, reference, frame);
  if (e.penumbra_pixels == 0) {
    ADD_FAILURE() << "the frame has no soft penumbra to judge";
    return 1.0;
  }
  return e.rmse_penumbra;
}

}  // namespace penumbra::test
