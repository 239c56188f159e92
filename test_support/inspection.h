#pragma once
// Pictures of a test to look at, off by default: with PENUMBRA_TEST_IMAGES=DIR set,
// save_for_inspection(name, image) writes DIR/<name>.png (the folder created as needed);
// without it, nothing. Every test of the repository uses this one switch.
//
//   test::save_for_inspection("ball_mask", rig.shadow_mask());
//   PENUMBRA_TEST_IMAGES=/tmp/look ctest --test-dir build/dev -R pmchss
#include <string>

#include "metrics/mask_image.h"

namespace penumbra::test {

// A mask or any one-channel image, in grey (0 black, 1 white); empty images are skipped.
void save_for_inspection(const std::string& name, const metrics::MaskImage& image);
// A heat map or a colour resource (TechniqueRig::read_rgba).
void save_for_inspection(const std::string& name, const metrics::RgbaImage& image);

}  // namespace penumbra::test
