#pragma once
// A bad-input case: what to run, what it must answer, and the input files it writes first.
//
//   # a second "passes" key would wipe the graph
//   run: penumbra graph {graph.json}
//   exit: 2
//   stderr: graph.json:3:3
//   stderr: duplicate key "passes"
//   --- graph.json
//   {"name": "g", "passes": [],
//     "passes": []}
//
// `env: NAME=value` lines set environment variables for the run. File names may hold folders
// (`--- shaders/x.json`). In `run` and `env`, {name} is the path of input file `name` and {out} a fresh output folder, which must
// still be empty after a failed run (no output left behind). Inside a file, {repeat N}text{end}
// stands for N copies of text, for inputs too large to keep (100,000 digits, 40,000 terms);
// a file headed `--- name base64` is decoded (binary glTF).
#include <string>
#include <utility>
#include <vector>

namespace penumbra::test {

struct BadInputCase {
  std::string name;         // the .case file's stem
  std::string description;  // its first comment line
  std::string run;          // "penumbra ..." or "penumbra-sandbox ..."
  std::vector<std::string> env;  // "NAME=value" set for the run ({name}, {dir} expand)
  int exit_code = 2;
  std::vector<std::string> stderr_contains;
  std::vector<std::pair<std::string, std::string>> files;  // name, content (decoded, expanded)
  std::string problem;      // a malformed .case file (the runner fails the case with it)
};

BadInputCase read_case(const std::string& path);
std::vector<std::string> list_cases(const std::string& dir);  // sorted *.case paths

}  // namespace penumbra::test
