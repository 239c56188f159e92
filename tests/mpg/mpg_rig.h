#pragma once
// Drives the mpg technique through plugin::TechniqueSession on the OSMesa test context and reads
// its resources back as metrics images (rows top to bottom).
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "metrics/mask_image.h"
#include "plugin/technique_session.h"
#include "scene/scene.h"

namespace penumbra::test {

class MpgRig {
 public:
  // width x height screen, shadow_size^2 shadow map; technique "mpg" with its defaults once a
  // scene is set.
  MpgRig(int width, int height, int shadow_size);
  ~MpgRig();

  plugin::TechniqueSession& session() { return *session_; }
  void set_scene(const scene::Scene& scene);
  // Each "k=v"; fails the test on error.
  void set(const std::vector<std::string>& assignments);
  // One frame; fails the test on error.
  void render();
  // One channel of a resource, rows top to bottom. Empty when the resource is absent.
  metrics::MaskImage read(const std::string& resource, int channel = 0);
  metrics::MaskImage shadow_mask() { return read("shadow_mask"); }
  // An RGBA8 resource (debug views), rows top to bottom.
  metrics::RgbaImage read_rgba(const std::string& resource);
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

// Writes `image` to MPG_TEST_IMAGES/<name>.png when that environment variable names a directory
// (for looking at the pictures); otherwise does nothing.
void save_for_inspection(const std::string& name, const metrics::MaskImage& image);
void save_for_inspection(const std::string& name, const metrics::RgbaImage& image);

}  // namespace penumbra::test
