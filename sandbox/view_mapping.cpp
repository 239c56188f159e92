#include "sandbox/view_mapping.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "metrics/heat_map.h"

namespace penumbra::sandbox {

std::optional<int> colour_map_index(const std::string& name) {
  for (int i = 0; i < int(std::size(kColourMapNames)); ++i)
    if (name == kColourMapNames[i]) return i;
  return std::nullopt;
}

glm::vec3 displayed_colour(int map, const glm::vec4& texel, float value, unsigned channel_mask, float lo, float hi) {
  const float scale = 1.0f / std::max(hi - lo, 1e-12f);
  if (map == 0) {
    const glm::vec3 mask(channel_mask & 1u, (channel_mask >> 1) & 1u, (channel_mask >> 2) & 1u);
    const glm::vec3 rgb = mask == glm::vec3(0.0f) ? glm::vec3(texel.a * float((channel_mask >> 3) & 1u)) : glm::vec3(texel) * mask;
    return glm::clamp((rgb - lo) * scale, 0.0f, 1.0f);
  }
  const float t = std::clamp((value - lo) * scale, 0.0f, 1.0f);
  if (map == 2) return glm::vec3(metrics::heat_color(t)) / 255.0f;
  if (map == 3) return diverging_color(t);
  return glm::vec3(t);
}

std::vector<float> histogram(const std::vector<float>& values, float lo, float hi, int bins) {
  std::vector<float> counts(static_cast<size_t>(std::max(bins, 1)), 0.0f);
  const float width = std::max(hi - lo, 1e-12f);
  for (float v : values) {
    if (!std::isfinite(v)) continue;
    const int b = std::clamp(static_cast<int>(std::floor((v - lo) / width * float(counts.size()))), 0, int(counts.size()) - 1);
    counts[static_cast<size_t>(b)] += 1.0f;
  }
  return counts;
}

glm::vec3 diverging_color(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  const glm::vec3 under(0.15f, 0.35f, 0.95f), middle(1.0f), over(0.95f, 0.2f, 0.15f);
  return t < 0.5f ? glm::mix(under, middle, t * 2.0f) : glm::mix(middle, over, t * 2.0f - 1.0f);
}

ViewZoom clamped(ViewZoom z) {
  z.zoom = std::clamp(std::isfinite(z.zoom) ? z.zoom : 1.0f, 1.0f, kMaxZoom);
  const float half = 0.5f / z.zoom;
  for (int i = 0; i < 2; ++i) z.center[i] = std::clamp(std::isfinite(z.center[i]) ? z.center[i] : 0.5f, half, 1.0f - half);
  return z;
}

ViewZoom zoom_about(ViewZoom z, float factor, glm::vec2 anchor) {
  const glm::vec2 uv = z.center + (anchor - 0.5f) / z.zoom;
  z.zoom = std::clamp(z.zoom * factor, 1.0f, kMaxZoom);
  z.center = uv - (anchor - 0.5f) / z.zoom;
  return clamped(z);
}

ViewZoom pan_by(ViewZoom z, glm::vec2 delta) {
  z.center -= delta / z.zoom;
  return clamped(z);
}

glm::vec4 zoomed_uv_rect(const ViewZoom& z, const glm::vec4& screen) {
  return {z.center.x + (screen.x - 0.5f) / z.zoom, z.center.y + (screen.y - 0.5f) / z.zoom, screen.z / z.zoom,
          screen.w / z.zoom};
}

glm::ivec4 fitted_rect(int frame_w, int frame_h, int tex_w, int tex_h) {
  if (tex_w <= 0 || tex_h <= 0 || frame_w <= 0 || frame_h <= 0) return {0, 0, std::max(frame_w, 0), std::max(frame_h, 0)};
  const double s = std::min(double(frame_w) / tex_w, double(frame_h) / tex_h);
  const int w = std::max(1, static_cast<int>(std::lround(tex_w * s)));
  const int h = std::max(1, static_cast<int>(std::lround(tex_h * s)));
  return {(frame_w - w) / 2, (frame_h - h) / 2, w, h};
}

glm::ivec4 inset_rect(int frame_w, int frame_h, int tex_w, int tex_h) {
  const int w = std::max(frame_w / 3, 1);
  int h = std::max(static_cast<int>(std::lround(float(w) * tex_h / std::max(tex_w, 1))), 1);
  h = std::min(h, frame_h);
  return {frame_w - w - 8, 8, w, h};
}

std::optional<glm::ivec2> pixel_to_texel(glm::ivec2 pixel, const glm::ivec4& rect, const glm::vec4& uv_rect,
                                         int tex_w, int tex_h) {
  if (pixel.x < rect.x || pixel.y < rect.y || pixel.x >= rect.x + rect.z || pixel.y >= rect.y + rect.w) return std::nullopt;
  const glm::vec2 f((pixel.x - rect.x + 0.5f) / rect.z, (pixel.y - rect.y + 0.5f) / rect.w);
  const glm::vec2 uv(uv_rect.x + f.x * uv_rect.z, uv_rect.y + f.y * uv_rect.w);
  if (uv.x < 0.0f || uv.y < 0.0f || uv.x >= 1.0f || uv.y >= 1.0f) return std::nullopt;
  return glm::ivec2(std::min(static_cast<int>(uv.x * tex_w), tex_w - 1), std::min(static_cast<int>(uv.y * tex_h), tex_h - 1));
}

}  // namespace penumbra::sandbox
