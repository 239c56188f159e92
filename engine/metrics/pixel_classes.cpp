#include "metrics/pixel_classes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace penumbra::metrics {
namespace {

// Discontinuities between neighbouring receiver pixels a and b.
bool normal_crease(const ReceiverGeometry& g, size_t a, size_t b) {
  return glm::dot(g.normals[a], g.normals[b]) < kNormalCreaseCos;
}

bool terminator(const ReceiverGeometry& g, size_t a, size_t b) { return (g.facing[a] > 0.0f) != (g.facing[b] > 0.0f); }

// Inverse depth bends at the middle of three pixels along one axis (a silhouette, a step, a fold).
bool depth_crease(const ReceiverGeometry& g, size_t before, size_t mid, size_t after) {
  const float inv_mid = 1.0f / g.view_depth[mid];
  const float second = 1.0f / g.view_depth[before] + 1.0f / g.view_depth[after] - 2.0f * inv_mid;
  return std::abs(second) > kDepthCreaseShare * inv_mid;
}

// Pixels where the G-buffer is discontinuous (before widening to kGeometricEdgeRadius).
std::vector<uint8_t> discontinuities(const ReceiverGeometry& g, const CoverageMask& coverage) {
  const int w = g.width, h = g.height;
  const auto receiver = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && g.view_depth[static_cast<size_t>(y) * w + x] > 0.0f &&
           (coverage.empty() || coverage[static_cast<size_t>(y) * w + x]);
  };
  std::vector<uint8_t> out(static_cast<size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!receiver(x, y)) continue;
      const size_t i = static_cast<size_t>(y) * w + x;
      bool edge = false;
      for (const glm::ivec2 axis : {glm::ivec2(1, 0), glm::ivec2(0, 1)}) {
        const int bx = x - axis.x, by = y - axis.y, ax = x + axis.x, ay = y + axis.y;
        const bool has_before = receiver(bx, by), has_after = receiver(ax, ay);
        // The image border is no discontinuity; background beside a receiver is one.
        const bool inside_before = bx >= 0 && by >= 0, inside_after = ax < w && ay < h;
        if ((inside_before && !has_before) || (inside_after && !has_after)) edge = true;
        if (has_before) {
          const size_t j = static_cast<size_t>(by) * w + bx;
          edge = edge || normal_crease(g, i, j) || terminator(g, i, j);
        }
        if (has_after) {
          const size_t j = static_cast<size_t>(ay) * w + ax;
          edge = edge || normal_crease(g, i, j) || terminator(g, i, j);
        }
        if (has_before && has_after)
          edge = edge || depth_crease(g, static_cast<size_t>(by) * w + bx, i, static_cast<size_t>(ay) * w + ax);
      }
      out[i] = edge;
    }
  return out;
}

}  // namespace

const char* pixel_class_name(PixelClass c) {
  switch (c) {
    case PixelClass::background: return "background";
    case PixelClass::lit: return "lit";
    case PixelClass::umbra: return "umbra";
    case PixelClass::soft_penumbra: return "soft penumbra";
    case PixelClass::geometric_edge: return "geometric edge";
    case PixelClass::outside_light: return "outside the light";
  }
  return "?";
}

ReceiverGeometry receiver_geometry(int width, int height, const std::vector<glm::vec4>& positions,
                                   const std::vector<glm::vec3>& normals, const scene::Light& light) {
  ReceiverGeometry g{width, height, {}, {}, {}, {}};
  const size_t n = std::min(positions.size(), normals.size());
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 p(positions[i]), normal = normals[i];
    const glm::vec3 to_light =
        light.type == scene::LightType::directional ? -light.direction : light.position - p;
    g.view_depth.push_back(positions[i].w);
    g.normals.push_back(normal);
    g.facing.push_back(positions[i].w > 0.0f ? glm::dot(normal, glm::normalize(to_light)) : 0.0f);
    g.reached.push_back(positions[i].w <= 0.0f || scene::light_reaches(light, p));
  }
  return g;
}

size_t PixelClasses::count(PixelClass c) const { return static_cast<size_t>(std::count(classes.begin(), classes.end(), c)); }

PixelClasses classify_pixels(const MaskImage& reference, const CoverageMask& coverage, const ReceiverGeometry* geometry) {
  const size_t n = reference.pixels.size();
  if (!coverage.empty() && coverage.size() != n) return {};
  if (geometry && (geometry->width != reference.width || geometry->height != reference.height ||
                   geometry->view_depth.size() != n || geometry->normals.size() != n || geometry->facing.size() != n ||
                   geometry->reached.size() != n))
    return {};
  PixelClasses out{reference.width, reference.height, std::vector<PixelClass>(n, PixelClass::background)};
  for (size_t i = 0; i < n; ++i) {
    if (!coverage.empty() && !coverage[i]) continue;
    const float v = reference.pixels[i];
    out.classes[i] = v <= kPenumbraLow    ? PixelClass::umbra
                     : v >= kPenumbraHigh ? PixelClass::lit
                                          : PixelClass::soft_penumbra;
  }
  if (!geometry) return out;
  const std::vector<uint8_t> seeds = discontinuities(*geometry, coverage);
  const int w = reference.width, h = reference.height, r = kGeometricEdgeRadius;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      if (out.classes[i] == PixelClass::background) continue;
      bool near = false;
      for (int dy = -r; dy <= r && !near; ++dy)
        for (int dx = -r; dx <= r && !near; ++dx) {
          const int sx = x + dx, sy = y + dy;
          near = sx >= 0 && sy >= 0 && sx < w && sy < h && seeds[static_cast<size_t>(sy) * w + sx];
        }
      if (near) out.classes[i] = PixelClass::geometric_edge;
    }
  for (size_t i = 0; i < n; ++i)
    if (out.classes[i] != PixelClass::background && !geometry->reached[i]) out.classes[i] = PixelClass::outside_light;
  return out;
}

CoverageMask judged_pixels(const PixelClasses& classes) {
  CoverageMask out(classes.classes.size(), 0);
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = classes.classes[i] != PixelClass::background && classes.classes[i] != PixelClass::outside_light;
  return out;
}

PenumbraReliability penumbra_reliability(const PixelClasses& c) {
  PenumbraReliability out;
  size_t receivers = 0, soft = 0;
  for (PixelClass k : c.classes) {
    receivers += k != PixelClass::background && k != PixelClass::outside_light;
    soft += k == PixelClass::soft_penumbra;
  }
  // 8-connected groups of soft-penumbra pixels (an explicit stack: groups can be large).
  std::vector<uint8_t> seen(c.classes.size(), 0);
  std::vector<size_t> stack;
  for (size_t start = 0; start < c.classes.size(); ++start) {
    if (seen[start] || c.classes[start] != PixelClass::soft_penumbra) continue;
    size_t size = 0;
    stack.push_back(start);
    seen[start] = 1;
    while (!stack.empty()) {
      const size_t i = stack.back();
      stack.pop_back();
      ++size;
      const int x = static_cast<int>(i % c.width), y = static_cast<int>(i / c.width);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= c.width || ny >= c.height) continue;
          const size_t j = static_cast<size_t>(ny) * c.width + nx;
          if (!seen[j] && c.classes[j] == PixelClass::soft_penumbra) {
            seen[j] = 1;
            stack.push_back(j);
          }
        }
    }
    ++out.groups;
    out.single_pixel_groups += size == 1;
  }
  if (soft == 0) {
    out.reason = "no soft penumbra";
  } else if (static_cast<double>(soft) < kMinPenumbraShare * static_cast<double>(receivers)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "soft penumbra is %.3g%% of the receivers (under %.3g%%)",
                  100.0 * static_cast<double>(soft) / static_cast<double>(receivers), 100.0 * kMinPenumbraShare);
    out.reason = buf;
  } else if (2 * out.single_pixel_groups > out.groups) {
    out.reason = std::to_string(out.single_pixel_groups) + " of its " + std::to_string(out.groups) +
                 " groups are single pixels";
  }
  out.reliable = out.reason.empty();
  return out;
}

RgbaImage pixel_class_image(const PixelClasses& c) {
  RgbaImage img{c.width, c.height, std::vector<uint8_t>(c.classes.size() * 4, 255)};
  for (size_t i = 0; i < c.classes.size(); ++i) {
    glm::u8vec3 rgb{128, 128, 128};
    switch (c.classes[i]) {
      case PixelClass::background: break;
      case PixelClass::lit: rgb = {255, 255, 255}; break;
      case PixelClass::umbra: rgb = {0, 0, 0}; break;
      case PixelClass::soft_penumbra: rgb = {255, 140, 0}; break;
      case PixelClass::geometric_edge: rgb = {40, 90, 255}; break;
      case PixelClass::outside_light: rgb = {50, 55, 80}; break;
    }
    img.pixels[i * 4] = rgb.r, img.pixels[i * 4 + 1] = rgb.g, img.pixels[i * 4 + 2] = rgb.b;
  }
  return img;
}

}  // namespace penumbra::metrics
