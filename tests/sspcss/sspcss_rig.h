#pragma once
// What the sspcss tests share: rendering any technique through the baseline tests' renderer
// (tests/baseline/baseline_frame.h), reading the technique's debug resources, the ray-traced
// reference of a rendered frame, and the scene built for the edge-awareness test.
#include <string>

#include <glm/glm.hpp>

#include "baseline_frame.h"
#include "metrics/mask_image.h"
#include "scene/scene.h"

namespace penumbra::test {

// First channel of a resource of the last rendered frame (rows top to bottom); `channel` picks
// another one. Empty when the frame has no such resource.
metrics::MaskImage read_resource(technique::TechniqueSession& session, const std::string& name, int channel = 0);

// Exact area-light visibility (Embree, 256 light samples) for the frame's G-buffer.
metrics::MaskImage trace_reference(const scene::Scene& scene, const RenderedFrame& frame);

// penumbra RMSE of `mask` against `reference` over the frame's receivers.
double penumbra_rmse(const metrics::MaskImage& mask, const metrics::MaskImage& reference,
                     const metrics::CoverageMask& coverage);

// Writes `image` to SSPCSS_TEST_IMAGES/<name>.png when that variable names a directory.
void save_for_inspection(const std::string& name, const metrics::MaskImage& image);

// The edge-awareness scene (edge_awareness_test.cpp says why it looks like this): a ground plane
// half in the umbra of a high slab (the umbra covers world x > 0) and, near the camera, a
// lit box whose right side (x = kBoxRight) hides part of that umbra.
inline constexpr float kBoxRight = 1.0f;  // world x of the box's right face, metres
scene::Scene edge_test_scene();

}  // namespace penumbra::test
