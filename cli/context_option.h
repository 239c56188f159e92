#pragma once
// The --context option shared by every GL subcommand.
#include <memory>
#include <optional>
#include <string>

#include "cli/options/args.h"
#include "gl/context.h"

namespace penumbra::cli {

inline OptionSpec context_option_spec() {
  return {"context", true, false, "glfw|osmesa|egl",
          "GL context (default: PENUMBRA_CONTEXT, else egl then osmesa)"};
}

// Creates the context named by --context (or the default); prints the error and returns null
// with *exit_code set when it fails.
// debug_output=false for timing runs: KHR_debug output slows some drivers down.
std::unique_ptr<gl::Context> open_context(const ParsedArgs& args, const std::string& command,
                                          int* exit_code, int width = 64, int height = 64,
                                          bool debug_output = true);

}  // namespace penumbra::cli
