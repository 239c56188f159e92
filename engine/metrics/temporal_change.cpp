#include "metrics/temporal_change.h"

#include <cmath>

namespace penumbra::metrics {

namespace {

// The previous frame's mask at the reprojection of `p`; false when no neighbour holds p's surface.
bool reprojected_value(const SurfaceFrame& prev, const glm::vec3& p, float relative_tolerance, float* value) {
  const glm::vec4 clip = prev.view_proj * glm::vec4(p, 1.0f);
  if (clip.w <= 0.0f) return false;
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  const int w = prev.mask.width, h = prev.mask.height;
  // Pixel centres at integer + 0.5; rows top to bottom, so NDC +y is row 0.
  const float fx = (0.5f * ndc.x + 0.5f) * w - 0.5f;
  const float fy = (0.5f - 0.5f * ndc.y) * h - 0.5f;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const float tx = fx - x0, ty = fy - y0;
  const float tolerance = relative_tolerance * clip.w;
  float sum = 0.0f, weight = 0.0f;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int x = x0 + i, y = y0 + j;
      if (x < 0 || y < 0 || x >= w || y >= h) continue;
      const glm::vec4& q = prev.position[static_cast<size_t>(y) * w + x];
      if (q.w <= 0.0f || glm::distance(glm::vec3(q), p) > tolerance) continue;
      const float wt = (i ? tx : 1.0f - tx) * (j ? ty : 1.0f - ty) + 1e-6f;
      sum += wt * prev.mask.at(x, y);
      weight += wt;
    }
  if (weight <= 0.0f) return false;
  *value = sum / weight;
  return true;
}

}  // namespace

Result<TemporalChange> temporal_change(const std::vector<SurfaceFrame>& frames, float relative_tolerance) {
  if (frames.size() < 2) return make_error("temporal change needs at least two frames", ErrorKind::internal);
  const int w = frames[0].mask.width, h = frames[0].mask.height;
  for (const SurfaceFrame& f : frames)
    if (f.mask.width != w || f.mask.height != h || f.position.size() != static_cast<size_t>(w) * h)
      return make_error("temporal change: every frame must have one mask and position size", ErrorKind::internal);
  TemporalChange out;
  double sum = 0.0;
  for (size_t t = 1; t < frames.size(); ++t) {
    const SurfaceFrame& prev = frames[t - 1];
    const SurfaceFrame& cur = frames[t];
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const glm::vec4& p = cur.position[static_cast<size_t>(y) * w + x];
        if (p.w <= 0.0f) continue;
        float before = 0.0f;
        if (!reprojected_value(prev, glm::vec3(p), relative_tolerance, &before)) {
          ++out.disoccluded;
          continue;
        }
        sum += std::abs(cur.mask.at(x, y) - before);
        ++out.pixels;
      }
  }
  out.mean_abs_change = out.pixels ? sum / static_cast<double>(out.pixels) : 0.0;
  return out;
}

}  // namespace penumbra::metrics
