// Runs every case of the bad-input corpus (cases/*.case, format in case_file.h) against the
// shipped binaries: the exit code is the contract's (2 bad input, never a signal), stderr names
// what the case says (file, option, location), every stderr line stays short, and a failed run
// leaves its output folder empty.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "case_file.h"
#include "test_support/temp_dir.h"

namespace penumbra::test {
namespace {

namespace fs = std::filesystem;

struct CommandResult {
  int exit_code = -1;
  int signal = 0;
  std::string err;
};

CommandResult run_command(const std::string& command, const std::string& err_file) {
  CommandResult r;
  const int status = std::system((command + " >/dev/null 2>" + err_file + " </dev/null").c_str());
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  std::ifstream in(err_file);
  std::stringstream s;
  s << in.rdbuf();
  r.err = s.str();
  return r;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

class BadInput : public ::testing::TestWithParam<std::string> {};

TEST_P(BadInput, AnswersAsTheContractSays) {
  const BadInputCase c = read_case(GetParam());
  ASSERT_TRUE(c.problem.empty()) << GetParam() << ": " << c.problem;
  SCOPED_TRACE(c.name + ": " + c.description);
  const fs::path dir = fresh_temp_dir("bad_input_" + c.name);
  fs::create_directories(dir / "out");
  std::string command = c.run, env;
  for (const std::string& e : c.env) env += e + " ";
  for (const auto& [name, content] : c.files) {
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name, std::ios::binary) << content;
    command = replace_all(command, "{" + name + "}", (dir / name).string());
  }
  for (std::string* text : {&command, &env}) {
    *text = replace_all(*text, "{out}", (dir / "out").string());
    *text = replace_all(*text, "{dir}", dir.string());
  }
  if (command.rfind("penumbra-sandbox ", 0) == 0) command = std::string(PENUMBRA_SANDBOX) + command.substr(16);
  else if (command.rfind("penumbra ", 0) == 0) command = std::string(PENUMBRA_CLI) + command.substr(8);
  else FAIL() << "run: must start with penumbra or penumbra-sandbox";

  CommandResult r = run_command("PENUMBRA_LOG=warn " + env + "timeout 60 " + command, (dir / "stderr.txt").string());
  EXPECT_EQ(r.signal, 0) << "killed by a signal\n" << command;
  EXPECT_EQ(r.exit_code, c.exit_code) << command << "\nstderr:\n" << r.err.substr(0, 2000);
  for (const std::string& want : c.stderr_contains)
    EXPECT_NE(r.err.find(want), std::string::npos) << "stderr lacks '" << want << "':\n" << r.err.substr(0, 2000);
  std::istringstream lines(r.err);
  for (std::string line; std::getline(lines, line);)
    EXPECT_LE(line.size(), 400u) << "a message line this long echoes input: " << line.substr(0, 200) << "...";
  if (r.exit_code != 0) {
    EXPECT_TRUE(fs::is_empty(dir / "out")) << "a failed run left output behind in " << (dir / "out");
  }
  fs::remove_all(dir);
}

std::string case_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = fs::path(info.param).stem().string();
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput,
                         ::testing::ValuesIn(list_cases(std::string(PENUMBRA_TEST_DATA_DIR) + "/cases")), case_name);

}  // namespace
}  // namespace penumbra::test
