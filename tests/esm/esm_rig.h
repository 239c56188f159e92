#pragma once
// Drives one technique through plugin::TechniqueSession on the OSMesa test context (any
// technique: the ESM tests compare esm with hard and the reference on the same frame) and reads
// resources back as metrics images (rows top to bottom).
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "metrics/mask_image.h"
#include "plugin/technique_session.h"
#include "scene/scene.h"

namespace penumbra::test {

class TechniqueRig {
 public:
  // width x height screen, shadow_size^2 shadow map.
  TechniqueRig(int width, int height, int shadow_size);
  ~TechniqueRig();

  plugin::TechniqueSession& session() { return *session_; }
  void set_scene(const scene::Scene& scene);
  // Switches technique (its parameters reset to their defaults); fails the test on error.
  void use(const std::string& technique);
  // Each "k=v"; fails the test on error.
  void set(const std::vector<std::string>& assignments);
  void set_shadow_size(int texels);
  // One frame; fails the test on error.
  void render();
  // One frame, returning its Status (bad-input tests).
  Status try_render() { return session_->render(); }
  // Channel `channel` of a resource, rows top to bottom. Empty when absent.
  metrics::MaskImage read(const std::string& resource, int channel = 0);
  metrics::MaskImage shadow_mask() { return read("shadow_mask"); }
  metrics::CoverageMask coverage();
  // G-buffer positions/normals of the last frame (rows top to bottom), for the Embree reference.
  void gbuffer(std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals, metrics::CoverageMask& coverage);

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::unique_ptr<plugin::TechniqueSession> session_;
};

// The exact hard shadow of the rig's last frame (its scene's light with size 0), ray-traced from
// that frame's G-buffer with K x K samples per pixel (box-filtered), rows top to bottom.
metrics::MaskImage exact_hard_reference(TechniqueRig& rig, const scene::Scene& scene, int pixel_samples = 4);

// Writes `image` to ESM_TEST_IMAGES/<name>.png when that environment variable names a
// directory (for looking at the pictures); otherwise does nothing.
void save_for_inspection(const std::string& name, const metrics::MaskImage& image);

}  // namespace penumbra::test
