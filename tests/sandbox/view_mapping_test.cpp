// The arithmetic the composer draws with and the pixel inspector reads through: zoom about a
// point keeps it in place, pan stays inside the image, a square texture keeps its aspect, and
// a frame pixel maps back to the texel drawn there.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "sandbox/view_mapping.h"

namespace penumbra::sandbox {
namespace {

glm::vec2 uv_at(const ViewZoom& z, glm::vec2 screen) {
  const glm::vec4 r = zoomed_uv_rect(z);
  return {r.x + screen.x * r.z, r.y + screen.y * r.w};
}

TEST(ViewMapping, ZoomAboutAPointKeepsItUnderTheCursor) {
  const glm::vec2 anchor(0.7f, 0.4f);
  const glm::vec2 before = uv_at({}, anchor);
  const ViewZoom z = zoom_about({}, 4.0f, anchor);
  EXPECT_FLOAT_EQ(z.zoom, 4.0f);
  EXPECT_NEAR(uv_at(z, anchor).x, before.x, 1e-5f);
  EXPECT_NEAR(uv_at(z, anchor).y, before.y, 1e-5f);
  EXPECT_FLOAT_EQ(zoom_about(z, 1000.0f, anchor).zoom, kMaxZoom);
  EXPECT_FLOAT_EQ(zoom_about(z, 1e-3f, anchor).zoom, 1.0f);
}

TEST(ViewMapping, PanAndClampKeepTheWindowInsideTheImage) {
  ViewZoom z = pan_by({.zoom = 2.0f}, {5.0f, -5.0f});
  const glm::vec4 r = zoomed_uv_rect(z);
  EXPECT_GE(r.x, 0.0f);
  EXPECT_LE(r.x + r.z, 1.0f + 1e-6f);
  EXPECT_GE(r.y, 0.0f);
  EXPECT_LE(r.y + r.w, 1.0f + 1e-6f);
  EXPECT_EQ(clamped({.zoom = 0.1f}).zoom, 1.0f);
  EXPECT_EQ(clamped({.zoom = 1.0f, .center = {0.9f, 0.1f}}).center, glm::vec2(0.5f));
}

TEST(ViewMapping, ASquareShadowMapStaysSquare) {
  const glm::ivec4 r = fitted_rect(1280, 720, 2048, 2048);
  EXPECT_EQ(r.z, r.w);
  EXPECT_EQ(r.w, 720);
  EXPECT_EQ(r.x, (1280 - 720) / 2);
  const glm::ivec4 inset = inset_rect(900, 600, 1024, 1024);
  EXPECT_EQ(inset.z, inset.w);
  EXPECT_EQ(inset.x + inset.z, 900 - 8);
}

TEST(ViewMapping, PixelToTexelFollowsRectAndZoom) {
  // A 100 x 50 texture over a 400 x 200 rect: 4 pixels a texel.
  EXPECT_EQ(pixel_to_texel({0, 0}, {0, 0, 400, 200}, {0, 0, 1, 1}, 100, 50), glm::ivec2(0, 0));
  EXPECT_EQ(pixel_to_texel({399, 199}, {0, 0, 400, 200}, {0, 0, 1, 1}, 100, 50), glm::ivec2(99, 49));
  EXPECT_EQ(pixel_to_texel({13, 9}, {0, 0, 400, 200}, {0, 0, 1, 1}, 100, 50), glm::ivec2(3, 2));
  EXPECT_FALSE(pixel_to_texel({400, 0}, {0, 0, 400, 200}, {0, 0, 1, 1}, 100, 50));
  // Zoom 4 about the centre: 16 pixels a texel, the frame's middle on the texture's middle.
  const glm::vec4 uv = zoomed_uv_rect({.zoom = 4.0f});
  EXPECT_EQ(pixel_to_texel({200, 100}, {0, 0, 400, 200}, uv, 100, 50), glm::ivec2(50, 25));
  EXPECT_EQ(pixel_to_texel({216, 100}, {0, 0, 400, 200}, uv, 100, 50), glm::ivec2(51, 25));
  // Letterboxed: outside the fitted rect there is no texel.
  EXPECT_FALSE(pixel_to_texel({5, 5}, {100, 0, 200, 200}, {0, 0, 1, 1}, 64, 64));
}

TEST(ViewMapping, HistogramCountsIntoEqualBinsWithOutsideValuesAtTheEnds) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> counts = histogram({0.0f, 0.1f, 0.26f, 0.5f, 0.99f, 1.0f, -3.0f, 7.0f, nan}, 0.0f, 1.0f, 4);
  EXPECT_EQ(counts, (std::vector<float>{3, 1, 1, 3}));  // -3 joins the first bin, 7 and 1.0 the last; NaN none
}

TEST(ViewMapping, DisplayedColourFollowsTheMapRangeAndChannels) {
  const glm::vec4 texel(0.2f, 0.4f, 0.6f, 0.8f);
  EXPECT_EQ(displayed_colour(1, texel, 0.5f, 0x7, 0.0f, 1.0f), glm::vec3(0.5f));   // grey
  EXPECT_EQ(displayed_colour(1, texel, 0.75f, 0x7, 0.5f, 1.0f), glm::vec3(0.5f));  // range
  EXPECT_EQ(displayed_colour(0, texel, 0.0f, 0x5, 0.0f, 1.0f), glm::vec3(0.2f, 0.0f, 0.6f));  // R and B
  EXPECT_EQ(displayed_colour(0, texel, 0.0f, 0x8, 0.0f, 1.0f), glm::vec3(0.8f));  // alpha alone, grey
  EXPECT_EQ(displayed_colour(3, texel, -0.25f, 0x7, -0.25f, 0.25f), diverging_color(0.0f));  // signed: blue end
  EXPECT_EQ(displayed_colour(3, texel, 0.0f, 0x7, -0.25f, 0.25f), glm::vec3(1.0f));  // zero is white
  EXPECT_GT(diverging_color(0.0f).b, 0.9f);
  EXPECT_GT(diverging_color(1.0f).r, 0.9f);
  EXPECT_EQ(colour_map_index("signed"), 3);
  EXPECT_FALSE(colour_map_index("rainbow"));
}

}  // namespace
}  // namespace penumbra::sandbox
