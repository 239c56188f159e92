#pragma once
// The esm tests' rig: the generic technique rig (test_support/technique_rig.h) over the built-in
// techniques (any of them: the ESM tests compare esm with hard and the reference on the same
// frame).
#include <string>

#include "metrics/mask_image.h"
#include "scene/scene.h"
#include "test_support/inspection.h"
#include "test_support/technique_rig.h"

namespace penumbra::test {

class EsmRig : public TechniqueRig {
 public:
  // width x height screen, shadow_size^2 shadow map; no technique until use(). The extended map's
  // textures (esm_depth, esm_edge, esm_edge_depth, esm_edge_near) stay readable after a frame.
  EsmRig(int width, int height, int shadow_size);
};

// The exact hard shadow of the rig's last frame (its scene's light with size 0), ray-traced from
// that frame's G-buffer with K x K samples per pixel (box-filtered), rows top to bottom.
metrics::MaskImage exact_hard_reference(TechniqueRig& rig, const scene::Scene& scene, int pixel_samples = 4);

}  // namespace penumbra::test
