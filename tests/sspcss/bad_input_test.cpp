// Bad input: out-of-range parameters are refused with their range; degenerate scenes (a light
// of size zero, the camera inside an object, nothing in the shadow map to block the light) give
// the hard shadow or full light, and never NaN in the mask or the debug resources.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "metrics/mask_metrics.h"
#include "sspcss_rig.h"

namespace penumbra::test {
namespace {

constexpr int kW = 160, kH = 120;

// Every texel finite; the mask in [0, 1]. Returns the count of texels that are not.
int bad_texels(const metrics::MaskImage& m, bool unit_range) {
  int bad = 0;
  for (float v : m.pixels)
    if (!std::isfinite(v) || (unit_range && (v < 0.0f || v > 1.0f))) ++bad;
  return bad;
}

void expect_sane(BaselineRenderer& r, const RenderedFrame& f, const std::string& what) {
  ASSERT_EQ(f.mask.pixels.size(), static_cast<size_t>(kW) * kH) << what;
  EXPECT_EQ(bad_texels(f.mask, true), 0) << what << ": shadow_mask";
  for (const char* debug : {"blocker_distance", "penumbra_width"})
    EXPECT_EQ(bad_texels(r.read(debug), false), 0) << what << ": " << debug;
  for (int c = 0; c < 4; ++c)
    EXPECT_EQ(bad_texels(r.read("projected_shadow_map", c), false), 0)
        << what << ": projected_shadow_map channel " << c;
}

scene::Scene ground_only() {
  scene::Scene s = builtin_scene("ball");
  s.meshes.resize(1);  // the ground (the ball scene adds it first)
  s.instances.resize(1);
  s.bounds = scene::compute_bounds(s);
  return s;
}

}  // namespace

TEST(SspcssBadInput, OutOfRangeParametersAreRefusedWithTheirRange) {
  BaselineRenderer r;
  r.render(builtin_scene("ball"), "sspcss", {}, 64, 48);
  technique::TechniqueSession& s = r.session();
  struct Case {
    const char* assignment;
    const char* range;
  };
  for (const Case& c : {Case{"poisson_taps=1000", "[4, 64]"}, Case{"separable_taps=2", "[3, 64]"},
                        Case{"depth_sigma=0", "[0.001, 1]"}, Case{"max_penumbra_px=0.5", "[1, 256]"},
                        Case{"light_size_scale=-1", "[0, 10]"}, Case{"fixed_radius_px=200", "[0, 128]"},
                        Case{"filter=box", "separable"}}) {
    Status st = s.set_param(c.assignment);
    ASSERT_FALSE(st) << c.assignment << " was accepted";
    const std::string name = std::string(c.assignment).substr(0, std::string(c.assignment).find('='));
    EXPECT_NE(st.error().message.find(name), std::string::npos) << st.error().message;
    EXPECT_NE(st.error().message.find(c.range), std::string::npos) << st.error().message;
  }
  EXPECT_EQ(s.params().get_int("poisson_taps"), 32);  // unchanged
  EXPECT_EQ(s.params().get_real("depth_sigma"), 0.1);
}

// No emitter, no penumbra: W_search = W_screen = 0, so the mask is the hard visibility of the
// preparation pass, and it matches the `hard` technique but for the anti-aliased edge pixels.
TEST(SspcssBadInput, ZeroSizeLightGivesTheHardShadow) {
  BaselineRenderer r;
  for (const char* filter : {"separable", "poisson"}) {
    scene::Scene s = builtin_scene("ball");
    s.light.size = 0.0f;
    RenderedFrame f = r.render(s, "sspcss", {{"filter", filter}}, kW, kH);
    expect_sane(r, f, filter);
    const metrics::MaskImage width = r.read("penumbra_width");
    const metrics::MaskImage hard = r.read("projected_shadow_map", 0);
    float widest = 0.0f, largest_difference = 0.0f;
    int shadowed = 0;
    for (size_t i = 0; i < f.mask.pixels.size(); ++i) {
      widest = std::max(widest, width.pixels[i]);
      largest_difference = std::max(largest_difference, std::abs(f.mask.pixels[i] - hard.pixels[i]));
      shadowed += f.mask.pixels[i] < 0.5f ? 1 : 0;
    }
    EXPECT_EQ(widest, 0.0f) << filter << ": W_screen without a light size";
    EXPECT_LT(largest_difference, 1e-3f) << filter << ": the mask is not the hard visibility";
    EXPECT_GT(shadowed, 100) << filter << ": the ball's shadow is gone";
    RenderedFrame h = r.render(s, "hard", {}, kW, kH);
    Result<metrics::MaskErrors> e = metrics::compare_masks(f.mask, h.mask, f.coverage);
    ASSERT_TRUE(e);
    std::printf("[ measure  ] %s, light size 0: RMSE against `hard` %.4f, max %.3f\n", filter, e->rmse, e->max_error);
    // Only the shadow's edge pixels differ (anti-aliased over the pixel here, one nearest
    // comparison there): measured 0.024 (160x120), bound 0.05.
    EXPECT_LT(e->rmse, 0.05) << filter;
  }
}

// The camera inside the ball: every pixel sees the ball's inside (or, where back faces are
// culled, the scene through it); whatever it sees, the mask is a number in [0, 1].
TEST(SspcssBadInput, CameraInsideGeometryGivesNoNaN) {
  BaselineRenderer r;
  scene::Scene s = builtin_scene("ball");
  s.camera = scene::Camera::look_at({0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -3.0f});  // the ball's centre
  for (const char* filter : {"separable", "poisson"}) {
    RenderedFrame f = r.render(s, "sspcss", {{"filter", filter}}, kW, kH);
    expect_sane(r, f, std::string("inside the ball, ") + filter);
  }
  // Against the ground at 1 cm: tiny view depths, huge W_screen, clamped.
  s.camera = scene::Camera::look_at({0.0f, 0.01f, 2.0f}, {0.0f, 0.0f, 1.9f});
  RenderedFrame f = r.render(s, "sspcss", {}, kW, kH);
  expect_sane(r, f, "1 cm over the ground");
}

// Nothing blocks the light (only the ground in the shadow map): fully lit, exactly 1. With the
// light below the ground every receiver faces away: exactly 0.
TEST(SspcssBadInput, NothingInTheShadowMapGivesFullLight) {
  BaselineRenderer r;
  scene::Scene s = ground_only();
  for (const char* filter : {"separable", "poisson"}) {
    RenderedFrame f = r.render(s, "sspcss", {{"filter", filter}}, kW, kH);
    expect_sane(r, f, std::string("ground only, ") + filter);
    int receivers = 0, lit = 0;
    for (size_t i = 0; i < f.mask.pixels.size(); ++i) {
      receivers += f.coverage[i];
      lit += f.coverage[i] && f.mask.pixels[i] == 1.0f ? 1 : 0;
    }
    EXPECT_GT(receivers, kW * kH / 4);
    EXPECT_EQ(lit, receivers) << filter;
  }
  s.light.direction = -s.light.direction;
  s.light.position = s.bounds.center() - 10.0f * s.light.direction;
  RenderedFrame f = r.render(s, "sspcss", {}, kW, kH);
  expect_sane(r, f, "light from below");
  int unlit = 0, receivers = 0;
  for (size_t i = 0; i < f.mask.pixels.size(); ++i) {
    receivers += f.coverage[i];
    unlit += f.coverage[i] && f.mask.pixels[i] == 0.0f ? 1 : 0;
  }
  EXPECT_EQ(unlit, receivers);
}

// The parameters at the ends of their ranges, and a 16x16 shadow map: still numbers in [0, 1].
TEST(SspcssBadInput, ExtremeParametersGiveNoNaN) {
  BaselineRenderer r;
  const scene::Scene s = builtin_scene("poles");
  using Params = std::map<std::string, std::string>;
  for (const Params& p :
       {Params{{"light_size_scale", "10"}, {"max_penumbra_px", "256"}, {"separable_taps", "3"}, {"depth_sigma", "0.001"}},
        Params{{"light_size_scale", "10"}, {"max_penumbra_px", "256"}, {"filter", "poisson"}, {"poisson_taps", "4"},
               {"depth_sigma", "1"}},
        Params{{"fixed_radius_px", "128"}, {"separable_taps", "64"}, {"range_term", "false"}},
        Params{{"receiver_footprint", "false"}, {"max_penumbra_px", "1"}}}) {
    std::string what;
    for (const auto& [k, v] : p) what += k + "=" + v + " ";
    expect_sane(r, r.render(s, "sspcss", p, kW, kH), what);
  }
  expect_sane(r, r.render(s, "sspcss", {}, kW, kH, 1, 16), "16x16 shadow map");
}

}  // namespace penumbra::test
