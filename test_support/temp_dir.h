#pragma once
// A fresh, empty folder for one test, named by the test and the process: two checkouts (or two
// ctest runs) testing at the same time never share, and so never delete, each other's files.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace penumbra::test {

inline std::filesystem::path fresh_temp_dir(const std::string& name) {
  namespace fs = std::filesystem;
  fs::path d = fs::temp_directory_path() / ("penumbra_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace penumbra::test
