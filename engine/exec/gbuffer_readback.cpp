#include "exec/gbuffer_readback.h"

#include <algorithm>
#include <cmath>

namespace penumbra::exec {

PixelRays pixel_rays(const glm::mat4& view, const glm::mat4& projection, int width, int height) {
  const glm::mat4 inverse_view = glm::inverse(view);
  const glm::mat4 inverse_projection = glm::inverse(projection);
  // The world-space ray through a point of the near plane, scaled to view depth 1.
  const auto ray_at = [&](float ndc_x, float ndc_y) {
    const glm::vec4 near_point = inverse_projection * glm::vec4(ndc_x, ndc_y, -1.0f, 1.0f);
    const glm::vec3 view_ray = glm::vec3(near_point) / near_point.w;
    return glm::vec3(inverse_view * glm::vec4(view_ray / -view_ray.z, 0.0f));
  };
  PixelRays r;
  r.origin = glm::vec3(inverse_view[3]);
  r.ray00 = ray_at(-1.0f, -1.0f);
  r.ray_dx = (ray_at(1.0f, -1.0f) - r.ray00) / static_cast<float>(std::max(width, 1));
  r.ray_dy = (ray_at(-1.0f, 1.0f) - r.ray00) / static_cast<float>(std::max(height, 1));
  return r;
}

glm::vec3 world_from_view_depth(const PixelRays& rays, int x, int y, float view_depth) {
  const glm::vec3 ray = rays.ray00 + (static_cast<float>(x) + 0.5f) * rays.ray_dx + (static_cast<float>(y) + 0.5f) * rays.ray_dy;
  return rays.origin + view_depth * ray;
}

namespace {
glm::vec2 octahedral_wrap(glm::vec2 v) {
  return (1.0f - glm::abs(glm::vec2(v.y, v.x))) * glm::vec2(v.x >= 0.0f ? 1.0f : -1.0f, v.y >= 0.0f ? 1.0f : -1.0f);
}
}  // namespace

glm::vec2 encode_octahedral_normal(glm::vec3 n) {
  n /= std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
  const glm::vec2 e = n.z >= 0.0f ? glm::vec2(n) : octahedral_wrap(glm::vec2(n));
  return e * 0.5f + 0.5f;
}

glm::vec3 decode_octahedral_normal(glm::vec2 stored) {
  const glm::vec2 e = stored * 2.0f - 1.0f;
  glm::vec3 n(e, 1.0f - std::abs(e.x) - std::abs(e.y));
  if (n.z < 0.0f) {
    const glm::vec2 w = octahedral_wrap(glm::vec2(n));
    n.x = w.x;
    n.y = w.y;
  }
  return glm::normalize(n);
}

std::vector<glm::vec4> read_positions(const gl::Texture& gbuffer_depth, const scene::Camera& camera, RowOrder rows) {
  const int w = gbuffer_depth.width(), h = gbuffer_depth.height();
  const std::vector<float> depth = gbuffer_depth.read();
  const int c = gbuffer_depth.info().channels;
  const PixelRays rays =
      pixel_rays(camera.view(), camera.projection(static_cast<float>(w) / static_cast<float>(h)), w, h);
  std::vector<glm::vec4> out(static_cast<size_t>(w) * h, glm::vec4(0.0f));
  for (int y = 0; y < h; ++y) {
    const int row = rows == RowOrder::top_down ? h - 1 - y : y;
    for (int x = 0; x < w; ++x) {
      const float d = depth[(static_cast<size_t>(y) * w + x) * c];
      if (d > 0.0f) out[static_cast<size_t>(row) * w + x] = glm::vec4(world_from_view_depth(rays, x, y, d), d);
    }
  }
  return out;
}

std::vector<glm::vec3> read_normals(const gl::Texture& gbuffer_normal) {
  const std::vector<float> stored = gbuffer_normal.read();
  const int c = gbuffer_normal.info().channels;
  std::vector<glm::vec3> out(stored.size() / c);
  for (size_t i = 0; i < out.size(); ++i) out[i] = decode_octahedral_normal({stored[i * c], stored[i * c + 1]});
  return out;
}

}  // namespace penumbra::exec
