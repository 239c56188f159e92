#pragma once
// The mpg tests' rig: the generic technique rig (test_support/technique_rig.h) over the
// built-in techniques, technique "mpg" selected with its defaults once a scene is set.
#include <string>

#include "metrics/mask_image.h"
#include "test_support/technique_rig.h"

namespace penumbra::test {

class MpgRig : public TechniqueRig {
 public:
  // width x height screen, shadow_size^2 shadow map.
  MpgRig(int width, int height, int shadow_size);
};

// Writes `image` to MPG_TEST_IMAGES/<name>.png when that environment variable names a directory
// (for looking at the pictures); otherwise does nothing.
void save_for_inspection(const std::string& name, const metrics::MaskImage& image);
void save_for_inspection(const std::string& name, const metrics::RgbaImage& image);

}  // namespace penumbra::test
