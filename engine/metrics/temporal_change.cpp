#include "metrics/temporal_change.h"

#include <cmath>

namespace penumbra::metrics {

namespace {

enum class Read { value, disoccluded, unmatched };

// The previous frame's mask at the reprojection of `p`, read as `how` says.
Read reprojected_value(const SurfaceFrame& prev, const glm::vec3& p, const Reprojection& how, float* value) {
  const glm::vec4 clip = prev.view_proj * glm::vec4(p, 1.0f);
  if (clip.w <= 0.0f) return Read::disoccluded;
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  const int w = prev.mask.width, h = prev.mask.height;
  // Pixel centres at integer + 0.5; rows top to bottom, so NDC +y is row 0.
  const float fx = (0.5f * ndc.x + 0.5f) * w - 0.5f;
  const float fy = (0.5f - 0.5f * ndc.y) * h - 0.5f;
  const float tolerance = how.relative_tolerance * clip.w;
  auto holds_p = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= w || y >= h) return false;
    const glm::vec4& q = prev.position[static_cast<size_t>(y) * w + x];
    return q.w > 0.0f && glm::distance(glm::vec3(q), p) <= tolerance;
  };
  if (how.match_within > 0.0f) {
    const float xn = std::round(fx), yn = std::round(fy);
    if (!holds_p(static_cast<int>(xn), static_cast<int>(yn))) return Read::disoccluded;
    if (std::abs(fx - xn) > how.match_within || std::abs(fy - yn) > how.match_within) return Read::unmatched;
    *value = prev.mask.at(static_cast<int>(xn), static_cast<int>(yn));
    return Read::value;
  }
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const float tx = fx - x0, ty = fy - y0;
  float sum = 0.0f, weight = 0.0f;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      if (!holds_p(x0 + i, y0 + j)) continue;
      const float wt = (i ? tx : 1.0f - tx) * (j ? ty : 1.0f - ty) + 1e-6f;
      sum += wt * prev.mask.at(x0 + i, y0 + j);
      weight += wt;
    }
  if (weight <= 0.0f) return Read::disoccluded;
  *value = sum / weight;
  return Read::value;
}

Status check_frames(const std::vector<SurfaceFrame>& frames) {
  if (frames.size() < 2) return make_error("temporal change needs at least two frames", ErrorKind::internal);
  const int w = frames[0].mask.width, h = frames[0].mask.height;
  for (const SurfaceFrame& f : frames)
    if (f.mask.width != w || f.mask.height != h || f.position.size() != static_cast<size_t>(w) * h)
      return make_error("temporal change: every frame must have one mask and position size", ErrorKind::internal);
  return {};
}

// Per pixel of `cur`: its mask minus the reprojected `prev` one; NaN where nothing is compared
// (no receiver, or not read: `counts` counts those).
std::vector<float> signed_change(const SurfaceFrame& prev, const SurfaceFrame& cur, const Reprojection& how,
                                 TemporalChange* counts) {
  const int w = cur.mask.width, h = cur.mask.height;
  std::vector<float> change(static_cast<size_t>(w) * h, std::nanf(""));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec4& p = cur.position[static_cast<size_t>(y) * w + x];
      if (p.w <= 0.0f) continue;
      float before = 0.0f;
      const Read read = reprojected_value(prev, glm::vec3(p), how, &before);
      if (read != Read::value) {
        ++(read == Read::disoccluded ? counts->disoccluded : counts->unmatched);
        continue;
      }
      change[static_cast<size_t>(y) * w + x] = cur.mask.at(x, y) - before;
    }
  return change;
}

}  // namespace

Result<TemporalChange> temporal_change(const std::vector<SurfaceFrame>& frames, const Reprojection& how) {
  if (Status s = check_frames(frames); !s) return s.error();
  TemporalChange out;
  double sum = 0.0;
  for (size_t t = 1; t < frames.size(); ++t)
    for (float c : signed_change(frames[t - 1], frames[t], how, &out))
      if (!std::isnan(c)) {
        sum += std::abs(c);
        ++out.pixels;
      }
  out.mean_abs_change = out.pixels ? sum / static_cast<double>(out.pixels) : 0.0;
  return out;
}

Result<TemporalChange> temporal_error(const std::vector<SurfaceFrame>& frames, const std::vector<SurfaceFrame>& truth,
                                      const Reprojection& how) {
  if (Status s = check_frames(frames); !s) return s.error();
  if (Status s = check_frames(truth); !s) return s.error();
  if (truth.size() != frames.size() || truth[0].mask.width != frames[0].mask.width ||
      truth[0].mask.height != frames[0].mask.height)
    return make_error("temporal error: the truth must have as many frames, of the same size", ErrorKind::internal);
  TemporalChange out;
  double sum = 0.0;
  for (size_t t = 1; t < frames.size(); ++t) {
    TemporalChange scratch;  // what each sequence could not read; counted below per pixel, once
    const std::vector<float> a = signed_change(frames[t - 1], frames[t], how, &scratch);
    const std::vector<float> b = signed_change(truth[t - 1], truth[t], how, &scratch);
    for (size_t i = 0; i < a.size(); ++i) {
      if (std::isnan(a[i]) || std::isnan(b[i])) {
        if (frames[t].position[i].w > 0.0f) ++out.disoccluded;
        continue;
      }
      sum += std::abs(a[i] - b[i]);
      ++out.pixels;
    }
  }
  out.mean_abs_change = out.pixels ? sum / static_cast<double>(out.pixels) : 0.0;
  return out;
}

}  // namespace penumbra::metrics
