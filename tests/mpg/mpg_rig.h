#pragma once
// The mpg tests' rig: the generic technique rig (test_support/technique_rig.h) over the
// built-in techniques, technique "mpg" selected with its defaults once a scene is set.
#include "test_support/inspection.h"
#include "test_support/technique_rig.h"

namespace penumbra::test {

class MpgRig : public TechniqueRig {
 public:
  // width x height screen, shadow_size^2 shadow map.
  MpgRig(int width, int height, int shadow_size);
};

}  // namespace penumbra::test
