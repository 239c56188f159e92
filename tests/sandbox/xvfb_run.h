#pragma once
// Running the sandbox binaries from tests: a shell command's exit code and output, and the
// same inside an X server of its own (xvfb-run) for the real window.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace penumbra::sandbox_test {

struct RunResult {
  int exit_code = -1;
  std::string output;  // stdout + stderr
};

inline RunResult run(const std::string& command) {
  RunResult r;
  std::string full = command + " 2>&1";
  FILE* pipe = popen(full.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, pipe)) r.output.append(buf, n);
  int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// ctest runs these tests in parallel and `xvfb-run -a` alone races for the same display
// number ("Xvfb failed to start"): start each process's search at its own number.
inline std::string xvfb() {
  if (run("command -v xvfb-run").exit_code != 0) return "";
  const int first_display = 100 + static_cast<int>(::getpid() % 800) * 8;
  return "xvfb-run -a -n " + std::to_string(first_display) + " -s \"-screen 0 1280x1024x24\" ";
}

// Runs `command` in the X server of `xvfb` and returns the COMMAND's exit code: xvfb-run's own
// status can be 5 when its temporary-directory clean-up races with a parallel xvfb-run.
inline RunResult run_in_xvfb(const std::string& xvfb_prefix, const std::string& command) {
  RunResult r = run(xvfb_prefix + "sh -c '" + command + "; echo penumbra_exit=$?'");
  const std::string marker = "penumbra_exit=";
  if (auto at = r.output.rfind(marker); at != std::string::npos) {
    r.exit_code = std::atoi(r.output.c_str() + at + marker.size());
    r.output.erase(at);
  }
  return r;
}

}  // namespace penumbra::sandbox_test
