// penumbra: headless command-line entry point. Each subcommand lives in its own cmd_*.cpp and
// registers itself (command.h).
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "cli/command.h"

namespace penumbra::cli {
std::vector<Command>& commands() {
  static std::vector<Command> all;
  return all;
}
}  // namespace penumbra::cli

using namespace penumbra::cli;

static void print_usage(FILE* to) {
  std::fprintf(to,
               "penumbra: render-graph framework for real-time soft shadows (headless CLI)\n\n"
               "usage: penumbra COMMAND [options]   (penumbra COMMAND --help for each)\n\ncommands:\n");
  auto sorted = commands();
  std::sort(sorted.begin(), sorted.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
  for (const Command& c : sorted) std::fprintf(to, "  %-12s %s\n", c.name.c_str(), c.summary.c_str());
  std::fprintf(to,
               "\nenvironment:\n"
               "  PENUMBRA_CONTEXT=glfw|osmesa|egl   GL context when --context is not given\n"
               "  PENUMBRA_LOG=trace|debug|info|warn|error   log level (default info)\n"
               "\nexit codes: 0 success, 2 bad input or usage, 1 internal error\n");
}

static void setup_logging() {
  auto logger = spdlog::stderr_color_mt("penumbra");
  spdlog::set_default_logger(logger);
  spdlog::set_pattern("[%l] %v");
  const char* level = std::getenv("PENUMBRA_LOG");
  spdlog::set_level(level ? spdlog::level::from_str(level) : spdlog::level::info);
}

int main(int argc, char** argv) {
  setup_logging();
  if (argc < 2) {
    print_usage(stderr);
    return 2;
  }
  std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_usage(stdout);
    return 0;
  }
  std::vector<std::string> args(argv + 2, argv + argc);
  for (const Command& c : commands()) {
    if (c.name != name) continue;
    try {
      return c.run(args);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "penumbra %s: internal error: %s\n", name.c_str(), e.what());
      return 1;
    }
  }
  std::fprintf(stderr, "penumbra: unknown command '%s' (run 'penumbra --help' for the list)\n", name.c_str());
  return 2;
}
