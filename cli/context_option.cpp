#include "cli/context_option.h"

#include <cstdio>

namespace penumbra::cli {

std::unique_ptr<gl::Context> open_context(const ParsedArgs& args, const std::string& command,
                                          int* exit_code, int width, int height, bool debug_output) {
  gl::ContextOptions options;
  options.debug_output = debug_output;
  options.width = width;
  options.height = height;
  options.visible = false;
  if (auto name = args.get("context")) {
    auto kind = gl::parse_context_kind(*name);
    if (!kind) {
      std::fprintf(stderr, "penumbra %s: %s\n", command.c_str(), kind.error().to_string().c_str());
      *exit_code = 2;
      return nullptr;
    }
    options.kind = *kind;
  }
  auto ctx = gl::create_context(options);
  if (!ctx) {
    std::fprintf(stderr, "penumbra %s: %s\n", command.c_str(), ctx.error().to_string().c_str());
    *exit_code = ctx.error().exit_code();
    return nullptr;
  }
  return std::move(*ctx);
}

}  // namespace penumbra::cli
