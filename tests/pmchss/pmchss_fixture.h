#pragma once
// The pmchss tests' rig: the generic technique rig (test_support/technique_rig.h) over the
// built-in techniques, technique "pmchss" selected with its defaults by set_scene().
#include "test_support/inspection.h"
#include "test_support/technique_rig.h"

namespace penumbra::test {

class PmchssRig : public TechniqueRig {
 public:
  // width x height screen, shadow_size^2 shadow map.
  PmchssRig(int width, int height, int shadow_size);
};

}  // namespace penumbra::test
