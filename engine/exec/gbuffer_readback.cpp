#include "exec/gbuffer_readback.h"

#include <cmath>

namespace penumbra::exec {

glm::vec3 world_from_view_depth(const glm::mat4& inverse_view, const glm::mat4& inverse_projection, int x, int y,
                                int width, int height, float view_depth) {
  const glm::vec2 ndc = (glm::vec2(x, y) + 0.5f) / glm::vec2(width, height) * 2.0f - 1.0f;
  const glm::vec4 near_point = inverse_projection * glm::vec4(ndc, -1.0f, 1.0f);
  const glm::vec3 ray = glm::vec3(near_point) / near_point.w;
  const glm::vec3 view_point = ray * (view_depth / -ray.z);
  return glm::vec3(inverse_view * glm::vec4(view_point, 1.0f));
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

std::vector<glm::vec4> read_positions(const gl::Texture& gbuffer_depth, const scene::Camera& camera) {
  const int w = gbuffer_depth.width(), h = gbuffer_depth.height();
  const std::vector<float> depth = gbuffer_depth.read();
  const int c = gbuffer_depth.info().channels;
  const glm::mat4 inverse_view = glm::inverse(camera.view());
  const glm::mat4 inverse_projection = glm::inverse(camera.projection(static_cast<float>(w) / static_cast<float>(h)));
  std::vector<glm::vec4> out(static_cast<size_t>(w) * h, glm::vec4(0.0f));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const float d = depth[i * c];
      if (d > 0.0f) out[i] = glm::vec4(world_from_view_depth(inverse_view, inverse_projection, x, y, w, h, d), d);
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
