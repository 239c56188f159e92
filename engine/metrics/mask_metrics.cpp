#include "metrics/mask_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "metrics/edge_error.h"

namespace penumbra::metrics {
namespace {

Status check_sizes(const MaskImage& a, const MaskImage& b, const CoverageMask& coverage) {
  const size_t n = static_cast<size_t>(a.width) * static_cast<size_t>(a.height);
  if (a.width != b.width || a.height != b.height || a.pixels.size() != n || b.pixels.size() != n) {
    Error e = make_error("mask sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                         " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
    e.where = "compare_masks";
    return e;
  }
  if (!coverage.empty() && coverage.size() != n) {
    Error e = make_error("coverage mask has " + std::to_string(coverage.size()) + " entries, expected " +
                         std::to_string(n));
    e.where = "compare_masks";
    return e;
  }
  return {};
}

// Separable 11-tap Gaussian (sigma 1.5) blur with zero padding; the weights need not be
// normalised because every statistic is divided by the blurred coverage.
std::vector<double> blur(const std::vector<double>& src, int w, int h) {
  static const std::array<double, 11> k = [] {
    std::array<double, 11> t{};
    for (int i = 0; i < 11; ++i) t[static_cast<size_t>(i)] = std::exp(-0.5 * (i - 5) * (i - 5) / (1.5 * 1.5));
    return t;
  }();
  std::vector<double> tmp(src.size(), 0.0), out(src.size(), 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0.0;
      for (int i = -5; i <= 5; ++i)
        if (x + i >= 0 && x + i < w) s += k[static_cast<size_t>(i + 5)] * src[static_cast<size_t>(y) * w + x + i];
      tmp[static_cast<size_t>(y) * w + x] = s;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0.0;
      for (int i = -5; i <= 5; ++i)
        if (y + i >= 0 && y + i < h) s += k[static_cast<size_t>(i + 5)] * tmp[static_cast<size_t>(y + i) * w + x];
      out[static_cast<size_t>(y) * w + x] = s;
    }
  return out;
}

}  // namespace

Result<double> masked_ssim(const MaskImage& a, const MaskImage& b, const CoverageMask& coverage) {
  if (Status s = check_sizes(a, b, coverage); !s) return s.error();
  const int w = a.width, h = a.height;
  const size_t n = a.pixels.size();
  std::vector<double> m(n), mx(n), my(n), mxx(n), myy(n), mxy(n);
  for (size_t i = 0; i < n; ++i) {
    const double c = coverage.empty() || coverage[i] ? 1.0 : 0.0;
    const double x = a.pixels[i], y = b.pixels[i];
    m[i] = c, mx[i] = c * x, my[i] = c * y, mxx[i] = c * x * x, myy[i] = c * y * y, mxy[i] = c * x * y;
  }
  const auto bm = blur(m, w, h), bx = blur(mx, w, h), by = blur(my, w, h);
  const auto bxx = blur(mxx, w, h), byy = blur(myy, w, h), bxy = blur(mxy, w, h);
  constexpr double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
  double sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!(coverage.empty() || coverage[i]) || bm[i] <= 0.0) continue;
    const double ux = bx[i] / bm[i], uy = by[i] / bm[i];
    const double vx = std::max(0.0, bxx[i] / bm[i] - ux * ux), vy = std::max(0.0, byy[i] / bm[i] - uy * uy);
    const double cxy = bxy[i] / bm[i] - ux * uy;
    const double num = (2.0 * ux * uy + C1) * (2.0 * cxy + C2);
    const double den = (ux * ux + uy * uy + C1) * (vx + vy + C2);
    sum += num / den;
    ++count;
  }
  return count ? sum / static_cast<double>(count) : 1.0;
}

Result<MaskErrors> compare_masks(const MaskImage& test, const MaskImage& ref, const CoverageMask& coverage) {
  if (Status s = check_sizes(test, ref, coverage); !s) return s.error();
  return compare_masks(test, ref, coverage, classify_pixels(ref, coverage));
}

Result<MaskErrors> compare_masks(const MaskImage& test, const MaskImage& ref, const CoverageMask& coverage,
                                 const PixelClasses& classes) {
  if (Status s = check_sizes(test, ref, coverage); !s) return s.error();
  if (classes.classes.size() != ref.pixels.size())
    return make_error("pixel classes of " + std::to_string(classes.width) + "x" + std::to_string(classes.height) +
                          " for masks of " + std::to_string(ref.width) + "x" + std::to_string(ref.height),
                      ErrorKind::internal);
  // Receivers the light does not reach are judged by nothing (their classes say which).
  CoverageMask judged = judged_pixels(classes);
  for (size_t i = 0; i < judged.size() && !coverage.empty(); ++i) judged[i] = judged[i] && coverage[i];
  MaskErrors e;
  double sq = 0.0, abs_sum = 0.0, sq_pen = 0.0, sq_geo = 0.0;
  for (size_t i = 0; i < ref.pixels.size(); ++i) {
    if (!judged[i]) continue;
    const double d = static_cast<double>(test.pixels[i]) - static_cast<double>(ref.pixels[i]);
    sq += d * d;
    abs_sum += std::abs(d);
    e.max_error = std::max(e.max_error, std::abs(d));
    ++e.pixels;
    if (classes.classes[i] == PixelClass::soft_penumbra) {
      sq_pen += d * d;
      ++e.penumbra_pixels;
    } else if (classes.classes[i] == PixelClass::geometric_edge) {
      sq_geo += d * d;
      ++e.geometric_edge_pixels;
    }
  }
  if (e.pixels) {
    e.rmse = std::sqrt(sq / static_cast<double>(e.pixels));
    e.mae = abs_sum / static_cast<double>(e.pixels);
  }
  if (e.penumbra_pixels) e.rmse_penumbra = std::sqrt(sq_pen / static_cast<double>(e.penumbra_pixels));
  if (e.geometric_edge_pixels) e.rmse_geometric_edge = std::sqrt(sq_geo / static_cast<double>(e.geometric_edge_pixels));
  e.reliability = penumbra_reliability(classes);
  Result<double> ssim = masked_ssim(test, ref, judged);
  if (!ssim) return ssim.error();
  e.ssim = *ssim;
  Result<EdgeError> edge = edge_error(test, ref, judged);
  if (!edge) return edge.error();
  e.edge_error = edge->error;
  e.edge_pixels = edge->pixels;
  return e;
}

}  // namespace penumbra::metrics
