#include "mpg_rig.h"

#include "techniques/builtin_techniques.h"

namespace penumbra::test {

MpgRig::MpgRig(int width, int height, int shadow_size)
    : TechniqueRig({.width = width, .height = height, .shadow_size = shadow_size, .technique = "mpg",
                    .techniques = register_builtin_techniques}) {}

}  // namespace penumbra::test
