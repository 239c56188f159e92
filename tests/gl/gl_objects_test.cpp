// GL objects on a real (OSMesa) context: compute and raster passes into textures, read back,
// exact values.
#include <gtest/gtest.h>

#include <cmath>

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
  for (Format f : {Format::R8, Format::R16F, Format::R32F, Format::RG16F, Format::RG32F, Format::RGBA8,
                   Format::RGBA16F, Format::RGBA32F, Format::DEPTH32F}) {
    gl::Texture t(f, 8, 4);
    t.clear(0.5f);
    std::vector<float> v = t.read();
    ASSERT_EQ(v.size(), 8u * 4u * t.info().channels) << t.info().name;
    for (float x : v) EXPECT_NEAR(x, 0.5f, 1.0f / 255.0f) << t.info().name;
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
