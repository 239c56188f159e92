#pragma once
// What the sspcss tests share: rendering any technique through the baseline tests' renderer
// (tests/baseline/baseline_frame.h; TechniqueRig::read for the technique's debug resources), the
// reference comparison (test_support/reference_comparison.h) and the scene built for the
// edge-awareness test.
#include <string>

#include <glm/glm.hpp>

#include "baseline_frame.h"
#include "metrics/mask_image.h"
#include "scene/scene.h"
#include "test_support/inspection.h"
#include "test_support/reference_comparison.h"

namespace penumbra::test {

// The edge-awareness scene (edge_awareness_test.cpp says why it looks like this): a ground plane
// half in the umbra of a high slab (the umbra covers world x > 0) and, near the camera, a
// lit box whose right side (x = kBoxRight) hides part of that umbra.
inline constexpr float kBoxRight = 1.0f;  // world x of the box's right face, metres
scene::Scene edge_test_scene();

}  // namespace penumbra::test
