// passes/sampling/sampling.glsl on the test GL context: the Vogel disk's radii grow with the
// sample index, stay inside the unit disk and give every sample the same area (r^2 = (i + 0.5) / n),
// its angles step by the golden angle from the rotation; the rotation noise lies in [0, 2 pi).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "gl/program.h"
#include "gl/texture.h"
#include "test_support/gl_context.h"
#include "test_support/temp_dir.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// Runs `body` (GLSL setting `vec4 v` for invocation `i` of `n`) once per i and reads the n
// results back. The shader includes sampling.glsl from the source tree, as the techniques do.
std::vector<glm::vec4> run(const std::string& body, int n) {
  test::gl_context();
  const fs::path dir = test::fresh_temp_dir("sampling_glsl");
  std::ofstream(dir / "probe.comp.glsl") << "#version 450 core\n#include \"sampling/sampling.glsl\"\n"
                                            "layout(local_size_x = 1) in;\n"
                                            "layout(rgba32f, binding = 0) uniform writeonly image2D dst;\n"
                                            "uniform int u_n;\n"
                                            "void main() {\n  int i = int(gl_GlobalInvocationID.x), n = u_n;\n"
                                            "  vec4 v = vec4(0.0);\n  " + body + "\n"
                                            "  imageStore(dst, ivec2(i, 0), v);\n}\n";
  gl::ShaderFileSystem files({dir, PENUMBRA_SOURCE_DIR}, false);
  gl::ShaderProgram p({.compute = "probe.comp.glsl"}, files);
  Status built = p.build();
  EXPECT_TRUE(built) << (built ? "" : built.error().to_string() + built.error().details);
  if (!built) return {};
  gl::Texture t(gl::Format::RGBA32F, n, 1);
  glUseProgram(p.id());
  p.program().set("u_n", n);
  glBindImageTexture(0, t.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glDispatchCompute(static_cast<GLuint>(n), 1, 1);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  const std::vector<float> texels = t.read();
  std::vector<glm::vec4> out;
  for (int i = 0; i < n; ++i) out.emplace_back(texels[4 * i], texels[4 * i + 1], texels[4 * i + 2], texels[4 * i + 3]);
  return out;
}

TEST(SamplingGlsl, VogelRadiiGrowStayInsideAndCoverEqualAreas) {
  for (int n : {4, 16, 64}) {
    const std::vector<glm::vec4> s = run("v.xy = vogel_disk_sample(i, n, 0.0);", n);
    ASSERT_EQ(s.size(), static_cast<size_t>(n));
    float previous = 0.0f;
    for (int i = 0; i < n; ++i) {
      const float r = glm::length(glm::vec2(s[i]));
      EXPECT_GT(r, previous) << "radius grows with i: " << i << " of " << n;
      EXPECT_LE(r, 1.0f) << i << " of " << n;
      // Area-uniform: the disk of radius r_i holds i + 0.5 of the n equal shares.
      EXPECT_NEAR(r * r, (i + 0.5f) / static_cast<float>(n), 1e-5f) << i << " of " << n;
      previous = r;
    }
  }
}

TEST(SamplingGlsl, VogelAnglesStepByTheGoldenAngleFromTheRotation) {
  const float phi = 1.0f;
  const std::vector<glm::vec4> s = run("v.xy = vogel_disk_sample(i, n, 1.0);", 16);
  ASSERT_EQ(s.size(), 16u);
  for (int i = 0; i < 16; ++i) {
    const float theta = static_cast<float>(i) * 2.4f + phi;
    const glm::vec2 unit = glm::normalize(glm::vec2(s[i]));
    EXPECT_NEAR(unit.x, std::cos(theta), 1e-4f) << i;
    EXPECT_NEAR(unit.y, std::sin(theta), 1e-4f) << i;
  }
}

TEST(SamplingGlsl, RotationNoiseLiesInZeroToTwoPiAndVariesPerPixel) {
  const std::vector<glm::vec4> s = run("v.x = noise_rotation(vec2(i % 16, i / 16));", 256);
  ASSERT_EQ(s.size(), 256u);
  float lo = 10.0f, hi = -1.0f;
  for (const glm::vec4& v : s) {
    EXPECT_GE(v.x, 0.0f);
    EXPECT_LT(v.x, 6.2831855f);
    lo = std::min(lo, v.x), hi = std::max(hi, v.x);
  }
  EXPECT_GT(hi - lo, 0.9f * 6.2831855f) << "a 16 x 16 block spans nearly every rotation";
}

}  // namespace
}  // namespace penumbra
