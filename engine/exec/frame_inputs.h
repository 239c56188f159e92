#pragma once
// The imported resources of a frame: what the executor hands every pass besides its slots.
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/cascades.h"
#include "scene/light.h"

namespace penumbra::exec {

class GpuScene;

struct FrameInputs {
  const GpuScene* scene = nullptr;
  scene::Camera camera;
  scene::Light light;
  scene::ShadowFrustum shadow;  // the light's frustum fitted to the scene
  scene::ShadowCascades cascades;  // count > 1: the map's tiles are cascades (scene/cascades.h)
  int screen_w = 0, screen_h = 0;  // pixels
  int shadow_size = 0;             // texels (square)
  std::uint32_t frame_index = 0;   // increases by one per executed frame

  float aspect() const { return screen_h > 0 ? float(screen_w) / float(screen_h) : 1.0f; }
  glm::mat4 view() const { return camera.view(); }
  glm::mat4 projection() const { return camera.projection(aspect()); }
};

}  // namespace penumbra::exec
