// Dev and asan builds (PENUMBRA_GL_STRICT) abort on the first GL error, naming the GL function;
// other builds leave the error to glGetError and KHR_debug.
#include <glad/gl.h>
#include <gtest/gtest.h>

#include "gl/debug_output.h"
#include "test_support/gl_context.h"

using namespace penumbra;

TEST(StrictGlErrors, ABadCallFailsLoudlyNamingTheFunction) {
  ::testing::FLAGS_gtest_death_test_style = "threadsafe";
  if (gl::strict_gl_errors()) {
    EXPECT_DEATH(
        {
          test::gl_context();
          glBindTexture(GL_TEXTURE_2D, 0xFFFFFFu);  // a name never generated
        },
        "GL_INVALID_OPERATION in glBindTexture");
  } else {
    test::gl_context();
    while (glGetError() != GL_NO_ERROR) {
    }
    glBindTexture(GL_TEXTURE_2D, 0xFFFFFFu);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  }
}
