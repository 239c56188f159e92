#pragma once
// The reference tests' rig: the generic technique rig (test_support/technique_rig.h) over the
// built-in techniques, on a built-in scene at size x size, rendering the `reference` technique.
#include <string>

#include "metrics/mask_image.h"
#include "techniques/builtin_techniques.h"
#include "test_support/technique_rig.h"

namespace penumbra::test {

struct ReferenceSession : TechniqueRig {
  explicit ReferenceSession(const std::string& scene_name, int size = 128)
      : TechniqueRig({.width = size, .height = size, .shadow_size = 2048, .technique = "reference",
                      .techniques = register_builtin_techniques}) {
    set_scene(builtin_scene(scene_name));
  }
  using TechniqueRig::set;
  void set(const std::string& kv) { TechniqueRig::set({kv}); }
  metrics::MaskImage mask() { return shadow_mask(); }
};

}  // namespace penumbra::test
