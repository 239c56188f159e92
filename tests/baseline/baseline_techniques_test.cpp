// Properties every baseline must have on every built-in scene: a valid mask with lit and
// shadowed receivers, a binary hard mask, and soft techniques that leave fully lit pixels at
// exactly 1.
#include <gtest/gtest.h>

#include <cmath>
#include <unordered_map>

#include "baseline_frame.h"
#include "scene/builtin_scenes.h"
#include "test_support/inspection.h"

namespace penumbra::test {
namespace {

constexpr int kW = 160, kH = 120;
const std::vector<std::string> kBaselines = {"hard", "pcf", "pcss"};

// Every built-in scene, plus `ball` under a spot light (perspective shadow map: the other
// branch of light_distance / light_size_uv_at).
std::vector<scene::Scene> test_scenes() {
  std::vector<scene::Scene> scenes;
  for (const std::string& name : scene::builtin_scene_names()) scenes.push_back(builtin_scene(name));
  scene::Scene spot = builtin_scene("ball");
  spot.name = "ball (spot light)";
  spot.light.type = scene::LightType::spot;
  spot.light.spot_angle = glm::radians(30.0f);
  scenes.push_back(std::move(spot));
  return scenes;
}

TEST(Baselines, EveryBuiltinSceneRendersWithEveryBaseline) {
  BaselineRenderer r;
  for (const scene::Scene& s : test_scenes()) {
    const std::string& name = s.name;
    for (const std::string& t : kBaselines) {
      SCOPED_TRACE(t + " on " + name);
      RenderedFrame f = r.render(s, t, {}, kW, kH);
      ASSERT_EQ(f.mask.pixels.size(), size_t(kW) * kH);
      save_for_inspection("all_" + s.name + "_" + t, f.mask);
      size_t lit = 0, shadowed = 0, receivers = 0;
      for (size_t i = 0; i < f.mask.pixels.size(); ++i) {
        const float v = f.mask.pixels[i];
        ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << "mask value " << v << " at pixel " << i;
        if (!f.coverage[i]) {
          EXPECT_EQ(v, 1.0f) << "background must be lit, pixel " << i;
          continue;
        }
        ++receivers;
        lit += v == 1.0f;
        shadowed += v < 0.5f;
      }
      EXPECT_GT(receivers, size_t(kW) * kH / 4);
      EXPECT_GT(lit, receivers / 4) << "too few fully lit receivers";
      EXPECT_GT(shadowed, size_t(20)) << "no shadow";
    }
  }
}

TEST(Baselines, HardMaskIsBinary) {
  BaselineRenderer r;
  for (const scene::Scene& s : test_scenes()) {
    RenderedFrame f = r.render(s, "hard", {}, kW, kH);
    for (size_t i = 0; i < f.mask.pixels.size(); ++i)
      ASSERT_TRUE(f.mask.pixels[i] == 0.0f || f.mask.pixels[i] == 1.0f)
          << s.name << ": pixel " << i << " = " << f.mask.pixels[i];
  }
}

metrics::RgbaImage upscaled(const metrics::RgbaImage& in, int k) {
  metrics::RgbaImage out{in.width * k, in.height * k, std::vector<uint8_t>(in.pixels.size() * k * k)};
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c)
        out.pixels[4 * (size_t(y) * out.width + x) + c] = in.pixels[4 * (size_t(y / k) * in.width + x / k) + c];
  return out;
}

// Points in shadow-map UV bucketed by a square cell, for "is any within r" queries.
class UvGrid {
 public:
  explicit UvGrid(float cell) : cell_(cell) {}
  void add(glm::vec2 p) { cells_[key(cell_of(p.x), cell_of(p.y))].push_back(p); }
  bool any_within(glm::vec2 p, float r) const {
    const int cx = cell_of(p.x), cy = cell_of(p.y), k = int(std::ceil(r / cell_));
    for (int y = cy - k; y <= cy + k; ++y)
      for (int x = cx - k; x <= cx + k; ++x) {
        auto it = cells_.find(key(x, y));
        if (it == cells_.end()) continue;
        for (const glm::vec2& q : it->second)
          if (glm::distance(p, q) <= r) return true;
      }
    return false;
  }

 private:
  int cell_of(float v) const { return int(std::floor(v / cell_)); }
  static long long key(int x, int y) { return (long long)x * 1000003LL + y; }
  float cell_;
  std::unordered_map<long long, std::vector<glm::vec2>> cells_;
};

// A covered 8-neighbour lies off this pixel's tangent plane: another surface.
bool at_depth_edge(const RenderedFrame& f, int x, int y) {
  const size_t i = size_t(y) * kW + x;
  const glm::vec3 n = glm::normalize(f.normals[i]);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= kW || ny >= kH || !f.coverage[size_t(ny) * kW + nx]) continue;
      const glm::vec3 d = f.positions[size_t(ny) * kW + nx] - f.positions[i];
      if (std::abs(glm::dot(d, n)) > 0.25f * glm::length(d)) return true;
    }
  return false;
}

// Receiver pixels that the hard mask calls lit and that lie farther (in shadow-map UV) from
// every hard-shadowed receiver pixel than the technique's largest kernel reach can see no
// blocker: they must be exactly 1 (no acne, no darkening from the filter itself).
// The reach is the kernel radius plus 1.5 texels (bilinear comparison footprint and the
// nearest-texel rounding of the hard mask), plus the pixel's own footprint in shadow-map UV
// (largest UV distance to a covered 8-neighbour): the hard shadow's true edge can lie anywhere
// between a lit pixel and its shadowed neighbour, and on the obliquely seen, obliquely lit
// ground one screen pixel spans several shadow-map texels.
// Pixels at depth edges count as possibly shadowed: a shadow the camera cannot see (behind a
// pole's base or the ball) borders the visible receivers only there.
void expect_fully_lit_stays_one(BaselineRenderer& r, const scene::Scene& s, const std::string& technique,
                                const std::map<std::string, std::string>& params, float reach_uv) {
  SCOPED_TRACE(technique + " on " + s.name);
  RenderedFrame hard = r.render(s, "hard", {}, kW, kH);
  RenderedFrame soft = r.render(s, technique, params, kW, kH);
  const scene::ShadowFrustum sf = scene::shadow_frustum(s.light, s.bounds);
  auto uv_of = [&](size_t i) {
    glm::vec4 c = sf.view_proj * glm::vec4(hard.positions[i], 1.0f);
    return glm::vec2(c) / c.w * 0.5f + 0.5f;
  };
  UvGrid shadowed(reach_uv);
  for (size_t i = 0; i < hard.mask.pixels.size(); ++i)
    if (hard.coverage[i] && (hard.mask.pixels[i] == 0.0f || at_depth_edge(hard, int(i % kW), int(i / kW))))
      shadowed.add(uv_of(i));
  // Debug view (save_for_inspection): the soft mask in grey, failing pixels red.
  metrics::RgbaImage debug{kW, kH, std::vector<uint8_t>(size_t(kW) * kH * 4, 255)};
  for (size_t i = 0; i < soft.mask.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) debug.pixels[4 * i + c] = uint8_t(255.0f * soft.mask.pixels[i]);
  size_t checked = 0, failed = 0;
  float worst = 1.0f;
  for (size_t i = 0; i < hard.mask.pixels.size(); ++i) {
    if (!hard.coverage[i] || hard.mask.pixels[i] != 1.0f) continue;
    const glm::vec2 uv = uv_of(i);
    float footprint = 0.0f;
    const int x = int(i % kW), y = int(i / kW);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= kW || ny >= kH || !hard.coverage[size_t(ny) * kW + nx]) continue;
        footprint = std::max(footprint, glm::distance(uv, uv_of(size_t(ny) * kW + nx)));
      }
    if (shadowed.any_within(uv, reach_uv + footprint)) continue;
    ++checked;
    if (soft.mask.pixels[i] != 1.0f) {
      ++failed;
      debug.pixels[4 * i] = 255, debug.pixels[4 * i + 1] = debug.pixels[4 * i + 2] = 0;
    }
  }
  if (failed) save_for_inspection("fully_lit_" + technique + "_" + s.name, upscaled(debug, 4));
  EXPECT_GT(checked, hard.mask.pixels.size() / 4);
  EXPECT_EQ(failed, 0u) << "of " << checked << " fully lit pixels; darkest " << worst;
}

TEST(Baselines, FullyLitPixelsStayExactlyOne) {
  BaselineRenderer r;
  const float texel = 1.0f / 2048.0f;
  for (const char* name : {"ball", "fence", "poles"}) {
    scene::Scene s = builtin_scene(name);
    // box 5: 2 texels; vogel: radius 2.5 texels.
    expect_fully_lit_stays_one(r, s, "pcf", {{"kernel", "box"}}, (2.0f + 1.5f) * texel);
    expect_fully_lit_stays_one(r, s, "pcf", {{"kernel", "vogel"}}, (2.5f + 1.5f) * texel);
    // PCSS: blocker search and filter radii are at most max_search_uv / 2, max_filter_uv / 2.
    expect_fully_lit_stays_one(r, s, "pcss", {{"max_search_uv", "0.05"}, {"max_filter_uv", "0.05"}},
                               0.025f + 1.5f * texel);
  }
}

}  // namespace
}  // namespace penumbra::test
