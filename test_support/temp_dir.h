#pragma once
// Folders for a test's files, named by the test and the process: two checkouts (or two ctest runs)
// testing at the same time never share, and so never delete, each other's files. The folders a
// test program made are removed when it ends with every test passed, and kept (their paths
// printed) when one failed, to look into.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace penumbra::test {

namespace detail {

class TempDirs {
 public:
  void add(const std::filesystem::path& dir) {
    for (const auto& d : dirs_)
      if (d == dir) return;
    dirs_.push_back(dir);
  }
  // Static destruction runs before gtest's own singleton goes (it was made first), so the verdict
  // can still be read. Only the process that made the folders removes them.
  ~TempDirs() {
    if (getpid() != owner_) return;
    const bool passed = ::testing::UnitTest::GetInstance()->Passed();
    for (const auto& d : dirs_) {
      std::error_code ec;
      if (passed)
        std::filesystem::remove_all(d, ec);
      else if (std::filesystem::exists(d, ec))
        std::fprintf(stderr, "kept for inspection: %s\n", d.c_str());
    }
  }

 private:
  pid_t owner_ = getpid();
  std::vector<std::filesystem::path> dirs_;
};

inline std::filesystem::path temp_dir_path(const std::string& name) {
  static TempDirs dirs;
  const std::filesystem::path d =
      std::filesystem::temp_directory_path() / ("penumbra_" + name + "_" + std::to_string(getpid()));
  dirs.add(d);
  return d;
}

}  // namespace detail

// $TMPDIR/penumbra_<name>_<pid>, created empty (emptied when called again).
inline std::filesystem::path fresh_temp_dir(const std::string& name) {
  const std::filesystem::path d = detail::temp_dir_path(name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// The same folder, created when missing and otherwise left as it is: for helpers that write one
// file a call into a folder they share.
inline std::filesystem::path temp_dir(const std::string& name) {
  const std::filesystem::path d = detail::temp_dir_path(name);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace penumbra::test
