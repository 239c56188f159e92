#pragma once
// Drives the baseline techniques headless for the tests: one TechniqueSession over the
// built-in registry and pass library, frames read back into CPU images (rows top to bottom,
// like metrics::MaskImage and reference::GBuffer).
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "metrics/mask_image.h"
#include "plugin/technique_session.h"
#include "scene/scene.h"

namespace penumbra::test {

struct RenderedFrame {
  metrics::MaskImage mask;            // shadow_mask, 1 = lit
  std::vector<glm::vec3> positions;   // world, NaN-free; only meaningful where coverage = 1
  std::vector<glm::vec3> normals;
  metrics::CoverageMask coverage;     // gbuffer_position.w > 0
  // Sum of the per-pass median times of the technique's own passes (not gbuffer, lighting):
  // GPU timestamps on a GPU, glFinish + CPU clock on llvmpipe (exec/pass_timer.h).
  double technique_ms = 0.0;
  std::string pass_ms;  // "shadow_map 0.112, pcf 0.054" (those passes' medians, ms)
};

class BaselineRenderer {
 public:
  BaselineRenderer();
  // Renders `frames` frames (timings are medians over them) of `technique` on `scene` with
  // `params` ("k" -> "v") at width x height, shadow map `shadow_size` texels.
  RenderedFrame render(const scene::Scene& scene, const std::string& technique,
                       const std::map<std::string, std::string>& params, int width, int height,
                       int frames = 1, int shadow_size = 2048);
  plugin::TechniqueSession& session() { return *session_; }
  const plugin::TechniqueRegistry& registry() const { return registry_; }

 private:
  plugin::TechniqueRegistry registry_;
  exec::PassLibrary library_;
  std::unique_ptr<plugin::TechniqueSession> session_;
};

// A built-in scene (fails the test on error).
scene::Scene builtin_scene(const std::string& name, const std::map<std::string, float>& params = {});

// World position -> pixel coordinates of the session's camera (top-left origin, pixel centres
// at +0.5), as metrics::penumbra_width expects.
glm::vec2 project_to_pixel(const scene::Camera& camera, const glm::vec3& world, int width, int height);

}  // namespace penumbra::test
