// The visualize pass: a heat view of a mask (0 -> blue, 1 -> red) and a grey view of a depth
// texture at another size, through a small test technique (visualize_graph.json).
#include <gtest/gtest.h>

#include "baseline_frame.h"
#include "test_support/gl_context.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::test {
namespace {

TEST(VisualizePass, HeatAndGreyMapsFollowTheInput) {
  gl_context();
  technique::TechniqueRegistry registry;
  register_builtin_techniques(registry);
  registry.add({.name = "visualize_test", .graph_file = "tests/baseline/visualize_graph.json"});
  exec::PassLibrary library = make_pass_library(registry);
  technique::TechniqueSession session(registry, library);
  session.set_scene(builtin_scene("ball"));
  ASSERT_TRUE(session.resize(96, 64));
  ASSERT_TRUE(session.set_shadow_size(512));
  Status s = session.set_technique("visualize_test");
  ASSERT_TRUE(s) << s.error().to_string();
  ASSERT_TRUE(session.render());

  std::vector<float> mask = session.executor().resource("shadow_mask")->read();
  std::vector<float> heat = session.executor().resource("mask_view")->read();  // RGBA in [0, 1]
  ASSERT_EQ(heat.size(), 4 * mask.size());
  size_t red = 0, blue = 0;
  for (size_t i = 0; i < mask.size(); ++i) {
    const float r = heat[4 * i], g = heat[4 * i + 1], b = heat[4 * i + 2];
    if (mask[i] == 1.0f) { EXPECT_TRUE(r == 1.0f && g == 0.0f && b == 0.0f); ++red; }
    if (mask[i] == 0.0f) { EXPECT_TRUE(r == 0.0f && g == 0.0f && b == 1.0f); ++blue; }
  }
  EXPECT_GT(red, 0u);
  EXPECT_GT(blue, 0u);

  // Grey view of the 512^2 depth map at 64x64: r = g = b = depth, clear depth (1) is white,
  // geometry is darker.
  gl::Texture* view = session.executor().resource("depth_view");
  ASSERT_NE(view, nullptr);
  EXPECT_EQ(view->width(), 64);
  std::vector<float> grey = view->read();
  size_t white = 0, geometry = 0;
  for (size_t i = 0; i < grey.size(); i += 4) {
    EXPECT_EQ(grey[i], grey[i + 1]);
    EXPECT_EQ(grey[i], grey[i + 2]);
    (grey[i] == 1.0f ? white : geometry)++;
  }
  EXPECT_GT(geometry, grey.size() / 4 / 8);  // a real share of the 64x64 texels
  EXPECT_GT(white, 0u);
}

}  // namespace
}  // namespace penumbra::test
