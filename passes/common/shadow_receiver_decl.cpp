#include "passes/common/shadow_receiver_decl.h"

namespace penumbra::passes {

exec::PassDeclBuilder shadow_receiver_pass(const char* name, const char* description) {
  using graph::Format;
  exec::PassDeclBuilder b(name);
  b.describe(description)
      .sampled("depth", {Format::R32F})
      .sampled("normal", {Format::RG16})
      .sampled("shadow_map", {Format::DEPTH32F})
      .imported("light", false);
  return b;
}

}  // namespace penumbra::passes
