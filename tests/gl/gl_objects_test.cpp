// GL objects on a real (OSMesa) context: compute and raster passes into textures, read back,
// exact values.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/timer_query.h"
#include "test_support/gl_context.h"

using namespace penumbra;
using gl::Format;

class GlObjects : public ::testing::Test {
 protected:
  void SetUp() override { test::gl_context(); }
};

TEST_F(GlObjects, EveryFormatClearsAndReadsBack) {
  for (int i = 0; i < graph::kFormatCount; ++i) {
    const auto f = static_cast<Format>(i);
    gl::Texture t(f, 8, 4);
    t.clear(0.5f);
    std::vector<float> v = t.read();
    ASSERT_EQ(v.size(), 8u * 4u * t.info().channels) << t.info().name;
    for (size_t k = 0; k < v.size(); ++k) {
      // RGB10A2's alpha has 2 bits: 0.5 lies halfway between 1/3 and 2/3.
      const bool two_bits = f == Format::RGB10A2 && k % 4 == 3;
      EXPECT_NEAR(v[k], 0.5f, two_bits ? 1.0f / 6.0f + 1e-6f : 1.0f / 255.0f) << t.info().name;
    }
  }
}

TEST_F(GlObjects, ComputeShaderWritesExactValuesToAnImage) {
  auto program = gl::build_compute_from_text(R"(#version 450 core
    layout(local_size_x = 8, local_size_y = 8) in;
    layout(r32f, binding = 0) uniform writeonly image2D dst;
    uniform float scale;
    void main() {
      ivec2 p = ivec2(gl_GlobalInvocationID.xy);
      imageStore(dst, p, vec4(float(p.x + 100 * p.y) * scale));
    })");
  ASSERT_TRUE(program) << program.error().to_string();
  EXPECT_EQ(program->local_size(), glm::ivec3(8, 8, 1));
  gl::Texture target(Format::R32F, 16, 16);
  program->set("scale", 0.5f);
  glUseProgram(program->id());
  glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glDispatchCompute(2, 2, 1);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  std::vector<float> v = target.read();
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) ASSERT_EQ(v[y * 16 + x], (x + 100 * y) * 0.5f) << x << "," << y;
}

// The 16-bit normalised four-channel formats through image stores with their GLSL qualifiers:
// signed values survive in RGBA16_SNORM, and both keep 16 bits (a step of 1/32767 or 1/65535).
TEST_F(GlObjects, SixteenBitNormalisedImagesKeepTheirRangeAndPrecision) {
  for (Format f : {Format::RGBA16, Format::RGBA16_SNORM}) {
    const bool snorm = f == Format::RGBA16_SNORM;
    auto program = gl::build_compute_from_text(std::string(R"(#version 450 core
      layout(local_size_x = 1) in;
      layout()") + graph::image_format_qualifier(f) + R"(, binding = 0) uniform writeonly image2D dst;
      uniform vec4 value;
      void main() { imageStore(dst, ivec2(0), value); })");
    ASSERT_TRUE(program) << program.error().to_string();
    gl::Texture target(f, 1, 1);
    const glm::vec4 value = snorm ? glm::vec4(-1.0f, -0.25f, 1.0f / 32767.0f, 0.75f)
                                  : glm::vec4(0.0f, 0.25f, 1.0f / 65535.0f, 1.0f);
    program->set("value", value);
    glUseProgram(program->id());
    glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, target.info().internal_format);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    const std::vector<float> v = target.read();
    ASSERT_EQ(v.size(), 4u);
    const float half_step = 0.5f / (snorm ? 32767.0f : 65535.0f);
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(v[static_cast<size_t>(c)], value[c], half_step + 1e-7f) << target.info().name << " " << c;
  }
}

TEST_F(GlObjects, RasterPassWritesColourAndDepth) {
  gl::ShaderProgram program({.vertex = "tests/gl/shaders/quad.vert.glsl",
                             .fragment = "tests/gl/shaders/quad.frag.glsl"});
  ASSERT_TRUE(program.build()) << program.last_error()->to_string();
  gl::Texture colour(Format::RGBA32F, 32, 32);
  gl::Texture depth(Format::DEPTH32F, 32, 32);
  gl::Framebuffer fb;
  fb.attach_color(0, colour);
  fb.attach_depth(depth);
  ASSERT_TRUE(fb.finish());
  fb.bind();
  glClearColor(0, 0, 0, 0);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glUseProgram(program.id());
  glDrawArrays(GL_TRIANGLES, 0, 6);  // a quad over the left half at depth 0.25 (NDC -0.5)
  glDisable(GL_DEPTH_TEST);
  glDeleteVertexArrays(1, &vao);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  std::vector<float> c = colour.read();
  std::vector<float> d = depth.read();
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      size_t i = y * 32 + x;
      bool inside = x < 16;
      EXPECT_EQ(c[i * 4 + 0], inside ? 0.25f : 0.0f);
      EXPECT_EQ(c[i * 4 + 1], inside ? float(x) + 0.5f : 0.0f);  // gl_FragCoord.x
      EXPECT_EQ(c[i * 4 + 3], inside ? 1.0f : 0.0f);
      EXPECT_FLOAT_EQ(d[i], inside ? 0.25f : 1.0f);
    }
}

TEST_F(GlObjects, BufferRoundTrip) {
  std::vector<int> data = {1, 2, 3, 4, 5};
  auto buf = gl::Buffer::from(std::span<const int>(data), true);
  int seven = 7;
  buf.update(&seven, sizeof seven, 2 * sizeof(int));
  std::vector<int> back = buf.read_as<int>();
  EXPECT_EQ(back, (std::vector<int>{1, 2, 7, 4, 5}));
  buf.clear_zero();
  EXPECT_EQ(buf.read_as<int>(), std::vector<int>(5, 0));
}

TEST_F(GlObjects, IncompleteFramebufferIsAnError) {
  gl::Framebuffer fb;  // no attachments at all
  Status s = fb.finish();
  EXPECT_FALSE(s);
}

TEST_F(GlObjects, TimestampQueriesBecomeAvailableAndIncrease) {
  gl::TimerQuery begin, end;
  begin.timestamp();
  gl::Texture t(Format::R32F, 64, 64);
  t.clear(1.0f);
  end.timestamp();
  glFinish();
  ASSERT_TRUE(begin.available());
  ASSERT_TRUE(end.available());
  EXPECT_GE(end.result_ns(), begin.result_ns());
}
