// penumbra info: which GL context we got and the limits that matter to the passes.
#include <cstdio>

#include "cli/command.h"
#include "cli/context_option.h"

namespace penumbra::cli {
namespace {

int cmd_info(const std::vector<std::string>& argv) {
  const std::vector<OptionSpec> specs = {context_option_spec()};
  if (help_requested(argv))
    return print_help("penumbra info [--context glfw|osmesa|egl]",
                                    "Creates a GL 4.5 core context and prints the backend, GL version,\n"
                                    "renderer, GLSL version and the limits the passes depend on.",
                                    specs);
  auto args = parse_args(argv, specs);
  if (!args) {
    std::fprintf(stderr, "penumbra info: %s\n", args.error().to_string().c_str());
    return 2;
  }
  if (!args->positionals.empty()) {
    std::fprintf(stderr, "penumbra info: unexpected argument '%s'\n", args->positionals[0].c_str());
    return 2;
  }
  int code = 0;
  auto ctx = open_context(*args, "info", &code);
  if (!ctx) return code;
  const gl::ContextInfo& i = ctx->info();
  std::printf("backend:              %s\n", i.backend.c_str());
  std::printf("GL version:           %s\n", i.version.c_str());
  std::printf("renderer:             %s\n", i.renderer.c_str());
  std::printf("vendor:               %s\n", i.vendor.c_str());
  std::printf("GLSL version:         %s\n", i.glsl_version.c_str());
  std::printf("software renderer:    %s\n", i.software ? "yes (timings use glFinish + CPU clock)" : "no");
  std::printf("max texture size:     %d\n", i.max_texture_size);
  std::printf("max image units:      %d\n", i.max_image_units);
  std::printf("max texture units:    %d\n", i.max_texture_units);
  std::printf("compute group count:  %d x %d x %d\n", i.max_compute_work_group_count[0],
              i.max_compute_work_group_count[1], i.max_compute_work_group_count[2]);
  std::printf("compute group size:   %d x %d x %d\n", i.max_compute_work_group_size[0],
              i.max_compute_work_group_size[1], i.max_compute_work_group_size[2]);
  std::printf("compute invocations:  %d\n", i.max_compute_work_group_invocations);
  std::printf("compute shared bytes: %d\n", i.max_compute_shared_memory);
  return 0;
}

const CommandRegistration reg{"info", "print the GL context, renderer and limits", cmd_info};

}  // namespace
}  // namespace penumbra::cli
