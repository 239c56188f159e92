#pragma once
// One GL 4.5 core context per test process, created on first use. OSMesa by default (CI has no
// GPU and no display); PENUMBRA_TEST_CONTEXT=egl runs the same suites on a GPU server.
#include "gl/context.h"

namespace penumbra::test {

gl::Context& gl_context();

}  // namespace penumbra::test
