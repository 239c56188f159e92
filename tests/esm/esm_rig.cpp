#include "esm_rig.h"

#include <gtest/gtest.h>

#include <limits>

#include "raytraced_reference.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::test {

EsmRig::EsmRig(int width, int height, int shadow_size)
    : TechniqueRig({.width = width, .height = height, .shadow_size = shadow_size,
                    .techniques = register_builtin_techniques,
                    // the extended map, which later passes would otherwise reuse before a read()
                    .keep_alive = {"esm_depth", "esm_edge", "esm_edge_depth", "esm_edge_near"}}) {}

metrics::MaskImage exact_hard_reference(TechniqueRig& rig, const scene::Scene& scene, int pixel_samples) {
  std::vector<glm::vec3> positions, normals;
  metrics::CoverageMask coverage;
  rig.gbuffer(positions, normals, coverage);
  Result<reference::RayScene> rs = reference::RayScene::build(scene);
  EXPECT_TRUE(rs);
  if (!rs) return {};
  scene::Light light = rig.session().light();
  light.size = 0.0f;
  reference::TraceOptions options{.samples = 1};
  options.pixel_samples = pixel_samples;
  options.camera = rig.session().camera();
  const technique::TechniqueSession& s = rig.session();
  return reference::trace_visibility(*rs, light, positions, normals, s.settings().screen_w, s.settings().screen_h,
                                     options, coverage);
}

}  // namespace penumbra::test
