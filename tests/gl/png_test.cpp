#include <gtest/gtest.h>

#include "test_support/temp_dir.h"
#include <stb/stb_image.h>

#include <filesystem>

#include "gl/texture.h"
#include "gl/texture_png.h"
#include "test_support/gl_context.h"

using namespace penumbra;
namespace fs = std::filesystem;

namespace {
struct Png {
  int w = 0, h = 0;
  std::vector<unsigned char> rgba;
};
Png load(const fs::path& p) {
  Png out;
  int n = 0;
  unsigned char* d = stbi_load(p.c_str(), &out.w, &out.h, &n, 4);
  if (d) out.rgba.assign(d, d + out.w * out.h * 4), stbi_image_free(d);
  return out;
}
}  // namespace

TEST(TexturePng, SingleChannelIsGreyAndTopRowFirst) {
  test::gl_context();
  gl::Texture t(gl::Format::R32F, 4, 2);
  std::vector<float> v = {0, 0, 0, 0, 1, 1, 1, 1};  // GL row 0 (bottom) black, row 1 (top) white
  t.upload(v.data());
  fs::path p = test::fresh_temp_dir("png_grey") / "grey.png";
  ASSERT_TRUE(gl::write_texture_png(t, p.string()));
  Png png = load(p);
  ASSERT_EQ(png.w, 4);
  ASSERT_EQ(png.h, 2);
  EXPECT_EQ(png.rgba[0], 255);          // first PNG row is the top: white
  EXPECT_EQ(png.rgba[4 * 4 + 0], 0);    // second row black
  EXPECT_EQ(png.rgba[3], 255);
  fs::remove(p);
}

TEST(TexturePng, DepthIsNormalisedOverItsRange) {
  test::gl_context();
  gl::Texture t(gl::Format::DEPTH32F, 2, 1);
  std::vector<float> v = {0.90f, 0.95f};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(t.id(), 0, 0, 0, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, v.data());
  fs::path p = test::fresh_temp_dir("png_depth") / "depth.png";
  ASSERT_TRUE(gl::write_texture_png(t, p.string()));
  Png png = load(p);
  EXPECT_EQ(png.rgba[0], 0);
  EXPECT_EQ(png.rgba[4], 255);
  fs::remove(p);
}

TEST(TexturePng, UnwritablePathIsAnErrorAndLeavesNoFile) {
  test::gl_context();
  gl::Texture t(gl::Format::RGBA8, 2, 2);
  t.clear(1.0f);
  Status s = gl::write_texture_png(t, "/nonexistent-dir/x.png");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().file, "/nonexistent-dir/x.png");
  EXPECT_FALSE(fs::exists("/nonexistent-dir/x.png.partial"));
}
