#pragma once
// Drives the pmchss technique through plugin::TechniqueSession on the OSMesa test context and
// reads its resources back as metrics images (rows top to bottom).
#include <memory>
#include <string>
#include <vector>

#include "metrics/mask_image.h"
#include "plugin/technique_session.h"
#include "scene/scene.h"

namespace penumbra::test {

class PmchssRig {
 public:
  // width x height screen, shadow_size^2 shadow map; technique "pmchss" with its defaults.
  PmchssRig(int width, int height, int shadow_size);
  ~PmchssRig();

  plugin::TechniqueSession& session() { return *session_; }
  void set_scene(const scene::Scene& scene);
  // Each "k=v"; fails the test on error.
  void set(const std::vector<std::string>& assignments);
  // One frame; fails the test on error.
  void render();
  // A single-channel resource (first channel), rows top to bottom. Empty when absent.
  metrics::MaskImage read(const std::string& resource);
  metrics::MaskImage shadow_mask() { return read("shadow_mask"); }
  // World-space height (gbuffer_position.y) per pixel, NaN on background; rows top to bottom.
  metrics::MaskImage world_y();
  // Receivers: 1 where gbuffer_position.w > 0.
  metrics::CoverageMask coverage();
  // G-buffer positions/normals for the Embree reference (rows top to bottom).
  void gbuffer(std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
               metrics::CoverageMask& coverage);

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::unique_ptr<plugin::TechniqueSession> session_;
};

// Renders `image` to PMCHSS_TEST_IMAGES/<name>.png when that environment variable names a
// directory (for looking at the pictures); otherwise does nothing.
void save_for_inspection(const std::string& name, const metrics::MaskImage& image);

}  // namespace penumbra::test
