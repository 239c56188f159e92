// glTF staging in the real window: a file's KHR_lights_punctual light decides where the shadow
// falls, and a model with no floor gets the ground plane (and loses it with --ground off). The
// glTF files are written here (a floating box), never taken from shared assets.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "gltf_box.h"
#include "image_stats.h"
#include "test_support/temp_dir.h"
#include "xvfb_run.h"

namespace {

namespace fs = std::filesystem;
using namespace penumbra::sandbox_test;

// Seen from above (image right = world +X, image up = world -Z), the box right of centre.
constexpr int kFrameW = 800, kFrameH = 450;
const std::string kView = " --technique hard --size 800x450 --shadow-size 1024 --camera -3,9,0.5:-3,0,0";

// The viewport: the frame, 1:1, in the window's right-most kFrameW columns (beside the panel).
int scene_x0(const Rgba& img) { return img.width - kFrameW; }

struct Shot {
  Rgba image;
  std::string output;
};

Shot screenshot(const std::string& x, const fs::path& dir, const std::string& name, const std::string& args) {
  const fs::path png = dir / (name + ".png");
  RunResult r = run_in_xvfb(x, std::string(SANDBOX_TEST_HOST) + args + kView + " --screenshot " + png.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return {read_rgba(png.string()), r.output};
}

// Mean x of the scene pixels at least 40 levels darker in `a` than in `b`; count in *n.
double darker_centroid_x(const Rgba& a, const Rgba& b, int* n) {
  double sum = 0.0;
  *n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = scene_x0(a); x < a.width; ++x)
      if (a.luminance(x, y) + 40.0 < b.luminance(x, y)) {
        sum += x;
        ++*n;
      }
  return *n ? sum / *n : 0.0;
}

// Neutral grey, neither dark nor the blue sky: the ground plane's material lit or shadowed.
int grey_pixels(const Rgba& img) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = scene_x0(img); x < img.width; ++x) {
      const unsigned char* p = img.at(x, y);
      if (std::abs(p[0] - p[1]) < 10 && std::abs(p[1] - p[2]) < 10 && p[1] > 30) ++n;
    }
  return n;
}

TEST(SandboxXvfbStaging, TheFilesOwnLightDecidesWhereTheShadowFalls) {
  const std::string x = xvfb();
  ASSERT_FALSE(x.empty()) << "xvfb-run is not installed: run scripts/setup.sh (installs xvfb)";
  const fs::path dir = penumbra::test::fresh_temp_dir("sandbox_xvfb_file_light");
  const Vec3 towards_plus_x{1.0f, -1.0f, 0.0f}, towards_minus_x{-1.0f, -1.0f, 0.0f};
  const std::string plus = write_floating_box(dir, "sun_plus_x", &towards_plus_x);
  const std::string minus = write_floating_box(dir, "sun_minus_x", &towards_minus_x);
  const std::string plain = write_floating_box(dir, "no_light");

  Shot a = screenshot(x, dir, "plus", " --scene " + plus);
  Shot b = screenshot(x, dir, "minus", " --scene " + minus);
  // The same direction given on the command line to a file without a light: the same frame.
  Shot c = screenshot(x, dir, "given", " --scene " + plain + " --light-dir 1,-1,0");
  ASSERT_GT(a.image.width, 0);
  ASSERT_EQ(a.image.width, b.image.width);
  ASSERT_EQ(a.image.width, c.image.width);

  int n_a = 0, n_b = 0;
  const double shadow_a = darker_centroid_x(a.image, b.image, &n_a);  // shadowed only under the +X light
  const double shadow_b = darker_centroid_x(b.image, a.image, &n_b);
  EXPECT_GT(n_a, 350) << "the +X light's shadow is missing";
  EXPECT_GT(n_b, 350) << "the -X light's shadow is missing";
  // World +X is image right: light travelling towards +X throws the shadow to the right.
  EXPECT_GT(shadow_a, shadow_b + 30.0) << "shadow centroids: +X light " << shadow_a << ", -X light " << shadow_b;
  // The file's light and --light-dir along the same direction cast the same shadow (their colour
  // and intensity may differ, so shadows are compared, not frames).
  int n_c = 0;
  const double shadow_c = darker_centroid_x(c.image, b.image, &n_c);
  EXPECT_NEAR(shadow_c, shadow_a, 4.0);
  EXPECT_NEAR(n_c, n_a, 0.1 * n_a);
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(SandboxXvfbStaging, AGroundPlaneGoesUnderAModelWithoutOne) {
  const std::string x = xvfb();
  ASSERT_FALSE(x.empty()) << "xvfb-run is not installed: run scripts/setup.sh (installs xvfb)";
  const fs::path dir = penumbra::test::fresh_temp_dir("sandbox_xvfb_ground");
  const std::string box = write_floating_box(dir, "box");
  Shot on = screenshot(x, dir, "on", " --scene " + box);
  Shot off = screenshot(x, dir, "off", " --scene " + box + " --ground off");
  ASSERT_GT(on.image.width, 0);
  ASSERT_GT(off.image.width, 0);
  const int grey_on = grey_pixels(on.image), grey_off = grey_pixels(off.image);
  // The plane is 3 x 3 units (the box's width plus its height on each side), ~180 px square here.
  EXPECT_GT(grey_on - grey_off, 10000) << "grey pixels: ground on " << grey_on << ", off " << grey_off;
  // Beside the box (below it in the image, on the plane, off its shadow) the plane is seen with
  // the ground on, the sky with it off.
  const int px = scene_x0(on.image) + kFrameW * 77 / 100, py = kFrameH * 65 / 100;
  const unsigned char* sky = off.image.at(px, py);
  EXPECT_GT(sky[2], sky[0] + 20) << "with --ground off the sky shows beside the box";
  const unsigned char* ground = on.image.at(px, py);
  EXPECT_LT(std::abs(ground[2] - ground[0]), 12) << "with the ground on a grey plane shows there";
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
