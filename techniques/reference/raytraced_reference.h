#pragma once
// Exact area-light visibility on the CPU: for each receiver pixel, the fraction of M stratified
// points on the light's emitter disk (scene::light_sample_points, shared with the GPU raster
// reference) that a shadow ray reaches unoccluded. A point light's disk faces each receiver
// (scene::point_light_sample). A light of size 0 is one point (or one parallel direction):
// one ray per pixel sample, whatever M says, which is the exact HARD shadow. A point behind the receiver's tangent plane
// (dot(normal, point - receiver) <= 0) counts as hidden by the receiver's own surface without a
// ray: with interpolated normals this puts the terminator of a tessellated sphere where the
// smooth surface has it (instead of a facet-dependent band where grazing rays graze the flat
// triangles), which is what shadow-map techniques and the raster reference see too. Output follows the shadow_mask contract:
// 1 = lit, 0 = umbra; background pixels are written as 1 and flagged 0 in the coverage mask.
//
//   Result<RayScene> rs = RayScene::build(scene);
//   GBuffer g = primary_gbuffer(*rs, scene.camera, 256, 256);
//   MaskImage ref = trace_visibility(*rs, scene.light, g, {.samples = 256,
//       .progress = [](float f) { fmt::print("\r{:.0f}%", 100 * f); }});
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "embree_scene.h"
#include "metrics/mask_image.h"
#include "scene/camera.h"
#include "scene/light.h"

namespace penumbra::reference {

// World-space surface positions and normals per pixel (rows top to bottom, like the screen).
struct GBuffer {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> positions;  // world units; NaN where coverage = 0
  std::vector<glm::vec3> normals;    // unit, world space, facing the viewer
  metrics::CoverageMask coverage;    // 1 = a surface was hit
};

// Primary rays through pixel centres (aspect = width / height, the camera's fov_y vertically).
// Normals are geometric, flipped to face the camera (what a shadow-ray offset needs).
GBuffer primary_gbuffer(const RayScene& scene, const scene::Camera& camera, int width, int height);

struct TraceOptions {
  int samples = 256;               // M light sample points (stratified)
  uint32_t seed = 0;               // light_sample_points seed
  int threads = 0;                 // 0 = std::thread::hardware_concurrency()
  // Shadow-ray origins move this far along the normal (world units); <= 0 picks 1e-4 of the
  // scene's bounding-box diagonal, enough to escape float self-intersection, small vs contact.
  float normal_offset = 0.0f;
  // Called on the calling thread only, with the fraction of rows done (0..1], ending with 1.
  std::function<void(float)> progress;
  // K x K sub-pixel samples per pixel (1: the pixel's own position). Each sample is where the
  // camera ray through a stratum centre of the pixel meets the receiver's tangent plane (the
  // pixel's position and normal), so the result is the visibility box-filtered over the pixel:
  // the anti-aliased ground truth of a hard shadow's edge. Needs `camera`.
  int pixel_samples = 1;
  std::optional<scene::Camera> camera;
  bool rows_bottom_up = false;  // positions are in GL row order (row 0 = bottom of the screen)
};

// Unit direction of the camera ray through the continuous screen point (x, y) in pixels,
// y measured from the top of a width x height screen (pixel centres at +0.5).
glm::vec3 camera_ray_direction(const scene::Camera& camera, int width, int height, float x, float y);

// positions/normals have width * height entries; a pixel whose position is not finite (or
// whose coverage is 0, when coverage is given) is background.
metrics::MaskImage trace_visibility(const RayScene& scene, const scene::Light& light,
                                    std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                    int width, int height, const TraceOptions& options = {},
                                    const metrics::CoverageMask& coverage = {});

inline metrics::MaskImage trace_visibility(const RayScene& scene, const scene::Light& light, const GBuffer& g,
                                           const TraceOptions& options = {}) {
  return trace_visibility(scene, light, g.positions, g.normals, g.width, g.height, options, g.coverage);
}

}  // namespace penumbra::reference
