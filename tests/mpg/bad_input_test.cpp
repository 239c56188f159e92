// Bad input gives clear errors, never garbage: out-of-range values are refused with their range,
// max_passes has a hard bound, and combinations that cannot work are errors naming the values.
#include <gtest/gtest.h>

#include "mpg_rig.h"
#include "mpg_settings.h"
#include "techniques/builtin_techniques.h"
#include "test_support/gl_context.h"

using namespace penumbra;

namespace {

void expect_refused(test::MpgRig& rig, const std::string& assignment, const std::string& expected_text) {
  Status s = rig.session().set_param(assignment);
  ASSERT_FALSE(s) << assignment << " was accepted";
  const std::string m = s.error().to_string();
  EXPECT_NE(m.find(assignment.substr(0, assignment.find('='))), std::string::npos) << m;
  EXPECT_NE(m.find(expected_text), std::string::npos) << m;
}

std::string render_error(test::MpgRig& rig) {
  Status s = rig.session().render();
  return s ? std::string() : s.error().to_string();
}

}  // namespace

TEST(MpgBadInput, OutOfRangeValuesNameTheirRange) {
  test::MpgRig rig(64, 48, 256);
  rig.set_scene(test::make_scene("ball"));
  expect_refused(rig, "max_passes=33", "[1, 32]");  // the hard bound (graph repeat allows 64)
  expect_refused(rig, "max_passes=0", "[1, 32]");
  expect_refused(rig, "poisson_taps=65", "[1, 64]");
  expect_refused(rig, "max_kernel=1", "[3, 63]");
  expect_refused(rig, "dilation_kernel=99", "[3, 63]");
  expect_refused(rig, "umbra_neighbourhood=64", "[3, 63]");
  expect_refused(rig, "alteration=separable", "multipass");  // lists the options
  EXPECT_EQ(rig.session().params().get_int("max_passes"), 10);  // unchanged
  EXPECT_EQ(rig.session().params().get_enum("alteration"), "multipass");
  rig.render();
}

// Kernel sizes are centred on the pixel: their declarations step by 2 from 3, so an even size is
// refused when set (naming the parameter and the valid values) and never reaches a frame.
TEST(MpgBadInput, EvenKernelSizesAreRefused) {
  test::MpgRig rig(64, 48, 256);
  rig.set_scene(test::make_scene("ball"));
  for (const char* even : {"max_kernel=20", "dilation_kernel=10", "umbra_neighbourhood=30"})
    expect_refused(rig, even, "must be odd; valid: 3, 5, 7, ..., 63");
  EXPECT_EQ(rig.session().params().get_int("max_kernel"), 19);  // unchanged
  rig.set({"max_kernel=21", "dilation_kernel=11"});
  EXPECT_EQ(render_error(rig), "");
}

// Section 5: the early-out neighbourhood must be at least the largest blur kernel; smaller is an
// error naming both values, not a silent clamp. Equal is allowed.
TEST(MpgBadInput, EarlyOutNeighbourhoodSmallerThanTheKernelIsAnError) {
  test::MpgRig rig(64, 48, 256);
  rig.set_scene(test::make_scene("ball"));
  rig.set({"umbra_early_out=true", "umbra_neighbourhood=15", "max_kernel=19"});
  const std::string m = render_error(rig);
  EXPECT_NE(m.find("umbra_neighbourhood (15 pixels) must be at least max_kernel (19 pixels)"), std::string::npos) << m;
  rig.set({"umbra_neighbourhood=19"});
  EXPECT_EQ(render_error(rig), "");
  rig.set({"max_kernel=29"});  // a live change: checked again every frame
  EXPECT_NE(render_error(rig).find("must be at least max_kernel (29 pixels)"), std::string::npos);
}

// A tiled blur pass keeps the pixels outside its tiles from two passes back: that holds only
// when it reads what the pass before it wrote. A graph that binds its input and output to two
// resources is refused when the frame runs, naming both, instead of leaving stale pixels.
TEST(MpgBadInput, TiledBlurBetweenTwoResourcesIsRefused) {
  test::gl_context();
  technique::TechniqueRegistry registry;
  register_builtin_techniques(registry);
  registry.add({.name = "misbound_tiled_blur", .graph_file = "tests/mpg/misbound_tiled_blur_graph.json"});
  exec::PassLibrary library = make_pass_library(registry);
  technique::TechniqueSession session(registry, library);
  session.set_scene(test::make_scene("ball"));
  ASSERT_TRUE(session.resize(test::kWidth, test::kHeight));
  Status s = session.set_technique("misbound_tiled_blur");
  ASSERT_TRUE(s) << s.error().to_string();
  Status r = session.render();
  ASSERT_FALSE(r) << "rendered";
  const std::string m = r.error().to_string();
  EXPECT_NE(m.find("blur[1]"), std::string::npos) << m;
  EXPECT_NE(m.find("'distance_map' and 'blurred'"), std::string::npos) << m;
}
