#pragma once
// Runs a command-line tool and captures what it prints (stdout and stderr together) and its
// exit code, for tests of the CLI end to end:
//   CliRun r = run_cli(PENUMBRA_CLI, "techniques --json");
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace penumbra::test {

struct CliRun {
  int exit_code = -1;  // -1: did not exit normally (a signal) or could not start
  std::string output;
};

inline CliRun run_cli(const std::string& executable, const std::string& args) {
  CliRun r;
  FILE* pipe = popen((executable + " " + args + " 2>&1 </dev/null").c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) r.output.append(buf, n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace penumbra::test
