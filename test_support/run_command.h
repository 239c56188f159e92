#pragma once
// Runs a command line through the shell, for tests of the command-line tools (`penumbra render
// --plugin-dir ...`): its exit code and what it wrote to stdout and stderr together.
//
//   CommandRun r = run_command(std::string(PENUMBRA_CLI) + " techniques --json");
//   ASSERT_EQ(r.exit_code, 0) << r.output;
#include <string>

namespace penumbra::test {

struct CommandRun {
  int exit_code = -1;  // -1 when the command did not exit normally (a signal) or did not start
  std::string output;  // stdout and stderr, interleaved
};

CommandRun run_command(const std::string& command_line);

// `text` quoted for the shell (single quotes).
std::string shell_quote(const std::string& text);

}  // namespace penumbra::test
