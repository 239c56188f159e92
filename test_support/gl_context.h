#pragma once
// The GL context of a test program: one GL 4.5 core context per process, made on first use and
// current from then on. OSMesa (llvmpipe: no GPU, no display) unless PENUMBRA_TEST_CONTEXT names
// another (`egl` runs the same tests on a GPU server). Aborts, saying why, when none can be made.
//
//   TEST_F(GlTest, ClearsToOne) { gl::Texture t(gl::Format::R16F, 4, 4); t.clear(1.0f); ... }
#include <gtest/gtest.h>

#include "gl/context.h"

namespace penumbra::test {

gl::Context& gl_context();

// A fixture whose tests run with that context current.
class GlTest : public ::testing::Test {
 protected:
  void SetUp() override { gl_context(); }
};

}  // namespace penumbra::test
