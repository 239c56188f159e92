#include "raytraced_reference.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

namespace penumbra::reference {
namespace {

// Runs row_job(y) for every row on `threads` threads (the caller is one of them), reporting
// progress from the calling thread only so callbacks never run concurrently.
template <class RowJob>
void for_each_row(int height, int threads, const std::function<void(float)>& progress, RowJob row_job) {
  std::atomic<int> next{0}, done{0};
  auto worker = [&](bool report) {
    for (int y = next.fetch_add(1); y < height; y = next.fetch_add(1)) {
      row_job(y);
      const int d = done.fetch_add(1) + 1;
      if (report && progress) progress(static_cast<float>(d) / static_cast<float>(height));
    }
  };
  const int n = std::max(1, threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int i = 1; i < n; ++i) pool.emplace_back(worker, false);
  worker(true);
  for (std::thread& t : pool) t.join();
  if (progress) progress(1.0f);
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Where the camera ray through screen point (x, y) meets the plane through `p` with normal `n`;
// `p` itself when the ray misses it (parallel, or the plane behind the camera).
glm::vec3 on_tangent_plane(const scene::Camera& camera, int width, int height, float x, float y,
                           const glm::vec3& p, const glm::vec3& n) {
  const glm::vec3 d = camera_ray_direction(camera, width, height, x, y);
  const float denom = glm::dot(d, n);
  if (std::abs(denom) < 1e-6f) return p;
  const float t = glm::dot(p - camera.position, n) / denom;
  return t > 0.0f ? camera.position + t * d : p;
}

}  // namespace

glm::vec3 camera_ray_direction(const scene::Camera& camera, int width, int height, float x, float y) {
  // Camera basis from the view matrix (rows of its rotation part are right, up, -forward).
  const glm::mat4 view = camera.view();
  const glm::vec3 right(view[0][0], view[1][0], view[2][0]), up(view[0][1], view[1][1], view[2][1]);
  const float tan_half = std::tan(0.5f * camera.fov_y), aspect = static_cast<float>(width) / height;
  const float sx = (2.0f * x / width - 1.0f) * tan_half * aspect;
  const float sy = (1.0f - 2.0f * y / height) * tan_half;
  return glm::normalize(camera.forward() + sx * right + sy * up);
}

GBuffer primary_gbuffer(const RayScene& scene, const scene::Camera& camera, int width, int height) {
  GBuffer g;
  g.width = width;
  g.height = height;
  const size_t n = static_cast<size_t>(std::max(0, width)) * static_cast<size_t>(std::max(0, height));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  g.positions.assign(n, glm::vec3(nan));
  g.normals.assign(n, glm::vec3(0.0f));
  g.coverage.assign(n, 0);
  if (n == 0) return g;
  const glm::vec3 forward = camera.forward();
  for_each_row(height, 0, nullptr, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const glm::vec3 dir = camera_ray_direction(camera, width, height, x + 0.5f, y + 0.5f);  // row 0 = top
      RayHit hit;
      if (!scene.intersect(camera.position, dir, hit, 0.0f, camera.far_plane / std::max(1e-6f, glm::dot(dir, forward))))
        continue;
      const size_t i = static_cast<size_t>(y) * width + x;
      g.positions[i] = camera.position + hit.t * dir;
      g.normals[i] = glm::dot(hit.geometric_normal, dir) > 0.0f ? -hit.geometric_normal : hit.geometric_normal;
      g.coverage[i] = 1;
    }
  });
  return g;
}

metrics::MaskImage trace_visibility(const RayScene& scene, const scene::Light& light,
                                    std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                    int width, int height, const TraceOptions& options,
                                    const metrics::CoverageMask& coverage) {
  metrics::MaskImage out(std::max(0, width), std::max(0, height), 1.0f);
  const size_t n = out.pixels.size();
  if (n == 0 || positions.size() < n || normals.size() < n) return out;
  // The one definition of the light shared with the GPU reference (scene/light.h): spot
  // samples are points, directional samples are parallel lights (the sun model).
  // A zero-size light is a single point (or direction): every sample would be the same ray.
  const int count = light.size > 0.0f ? std::max(1, options.samples) : 1;
  const std::vector<scene::LightSample> samples = scene::light_samples(light, scene.bounds(), count, options.seed);
  const bool point_light = light.type == scene::LightType::point;
  const int k = options.camera ? std::max(1, options.pixel_samples) : 1;
  const float far = 1e30f;
  const float diagonal = scene.bounds().empty() ? 1.0f : glm::length(scene.bounds().extent());
  const float offset = options.normal_offset > 0.0f ? options.normal_offset : 1e-4f * diagonal;
  const float inv_m = 1.0f / static_cast<float>(samples.size() * k * k);
  // Visibility of the light from one receiver point.
  auto unoccluded_from = [&](const glm::vec3& receiver, const glm::vec3& nrm, bool has_normal) {
    const glm::vec3 origin = receiver + offset * nrm;
    int unoccluded = 0;
    // Points: d = sample - origin (not normalised), so t in (0, 1) spans exactly receiver ->
    // emitter. Parallel lights: d = -direction, t up to infinity.
    for (const scene::LightSample& s : samples) {
      const glm::vec3 point = point_light ? scene::point_light_sample(light, s.disk, origin) : s.point;
      const glm::vec3 d = s.is_point ? point - origin : -s.direction;
      // Smooth-surface terminator: a sample behind the receiver's (interpolated) tangent
      // plane is hidden by the receiver's own surface (see TraceOptions::normal_offset).
      if (has_normal && glm::dot(nrm, d) <= 0.0f) continue;
      if (!scene.occluded(origin, d, 0.0f, s.is_point ? 1.0f : far)) ++unoccluded;
    }
    return unoccluded;
  };
  for_each_row(out.height, options.threads, options.progress, [&](int y) {
    for (int x = 0; x < out.width; ++x) {
      const size_t i = static_cast<size_t>(y) * out.width + x;
      if ((!coverage.empty() && (i >= coverage.size() || !coverage[i])) || !finite(positions[i])) continue;
      const glm::vec3 nrm = finite(normals[i]) ? normals[i] : glm::vec3(0.0f);
      const bool has_normal = glm::dot(nrm, nrm) > 0.25f;
      int unoccluded = 0;
      if (k == 1) {
        unoccluded = unoccluded_from(positions[i], nrm, has_normal);
      } else {  // stratum centres of the pixel, on the receiver's tangent plane
        const float top_row = options.rows_bottom_up ? static_cast<float>(out.height - 1 - y) : static_cast<float>(y);
        for (int sy = 0; sy < k; ++sy)
          for (int sx = 0; sx < k; ++sx) {
            const float px = static_cast<float>(x) + (sx + 0.5f) / k, py = top_row + (sy + 0.5f) / k;
            const glm::vec3 p = has_normal ? on_tangent_plane(*options.camera, out.width, out.height, px, py,
                                                              positions[i], nrm)
                                           : positions[i];
            unoccluded += unoccluded_from(p, nrm, has_normal);
          }
      }
      out.pixels[i] = static_cast<float>(unoccluded) * inv_m;
    }
  });
  return out;
}

}  // namespace penumbra::reference
