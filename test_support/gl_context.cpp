#include "test_support/gl_context.h"

#include <cstdio>
#include <cstdlib>
#include <memory>

namespace penumbra::test {

gl::Context& gl_context() {
  static std::unique_ptr<gl::Context> ctx = [] {
    gl::ContextOptions options;
    options.kind = gl::ContextKind::osmesa;
    if (const char* k = std::getenv("PENUMBRA_TEST_CONTEXT"); k && *k) {
      if (auto kind = gl::parse_context_kind(k)) options.kind = *kind;
    }
    options.width = options.height = 16;
    auto created = gl::create_context(options);
    if (!created) {
      std::fprintf(stderr, "cannot create the test GL context: %s\n", created.error().to_string().c_str());
      std::abort();
    }
    return std::move(*created);
  }();
  ctx->make_current();
  return *ctx;
}

}  // namespace penumbra::test
