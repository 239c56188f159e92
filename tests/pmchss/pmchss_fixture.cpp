#include "pmchss_fixture.h"

#include "techniques/builtin_techniques.h"

namespace penumbra::test {

PmchssRig::PmchssRig(int width, int height, int shadow_size)
    : TechniqueRig({.width = width, .height = height, .shadow_size = shadow_size, .technique = "pmchss",
                    .techniques = register_builtin_techniques}) {}

}  // namespace penumbra::test
