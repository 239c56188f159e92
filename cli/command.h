#pragma once
// A CLI subcommand registers itself with one line in its own file:
//   static const CommandRegistration reg{"info", "print the GL context ...", cmd_info};
// Exit codes (docs/architecture.md): 0 success, 2 bad input or usage, 1 internal error.
#include <functional>
#include <string>
#include <vector>

namespace penumbra::cli {

using CommandFn = int (*)(const std::vector<std::string>& args);

struct Command {
  std::string name;
  std::string summary;
  CommandFn run;
};

std::vector<Command>& commands();

struct CommandRegistration {
  CommandRegistration(std::string name, std::string summary, CommandFn fn) {
    commands().push_back({std::move(name), std::move(summary), fn});
  }
};

}  // namespace penumbra::cli
