#pragma once
// The pmchss tests' rig: the generic technique rig (test_support/technique_rig.h) over the
// built-in techniques, technique "pmchss" selected with its defaults by set_scene().
#include <string>

#include "metrics/mask_image.h"
#include "test_support/technique_rig.h"

namespace penumbra::test {

class PmchssRig : public TechniqueRig {
 public:
  // width x height screen, shadow_size^2 shadow map.
  PmchssRig(int width, int height, int shadow_size);
};

// Renders `image` to PMCHSS_TEST_IMAGES/<name>.png when that environment variable names a
// directory (for looking at the pictures); otherwise does nothing.
void save_for_inspection(const std::string& name, const metrics::MaskImage& image);

}  // namespace penumbra::test
