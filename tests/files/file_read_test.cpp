// read_file_whole and check_directory: what a user gets for a device, a pipe that never ends, a
// file over the cap, a folder where a file belongs and a file where a folder belongs.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <csignal>
#include <fstream>
#include <thread>

#include "test_support/temp_dir.h"
#include "util/file_read.h"
#include "util/file_write.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ReadFileWhole, ADeviceThatNeverEndsIsRefusedBeforeReading) {
  Result<std::string> r = read_file_whole("/dev/zero");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().file, "/dev/zero");
  EXPECT_TRUE(contains(r.error().message, "is a character device, not a regular file")) << r.error().message;
  EXPECT_EQ(r.error().exit_code(), 2);
}

TEST(ReadFileWhole, APipeIsReadUpToTheCapThenRefused) {
  const fs::path dir = test::fresh_temp_dir("read_pipe");
  const fs::path fifo = dir / "endless";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // The writer stops when the reader closes (EPIPE): it would write forever otherwise.
  std::thread writer([&] {
    std::ofstream out(fifo, std::ios::binary);
    const std::string block(4096, 'x');
    for (int i = 0; i < 1024 && out; ++i) out << block;  // 4 MiB, far past the cap below
  });
  ::signal(SIGPIPE, SIG_IGN);
  Result<std::string> r = read_file_whole(fifo.string(), 64 * 1024);
  writer.join();
  ASSERT_FALSE(r);
  EXPECT_TRUE(contains(r.error().message, "larger than 65536 bytes")) << r.error().message;
  fs::remove_all(dir);
}

TEST(ReadFileWhole, AShortPipeIsRead) {
  const fs::path dir = test::fresh_temp_dir("read_short_pipe");
  const fs::path fifo = dir / "short";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo) << "[{\"wait\": 1}]"; });
  Result<std::string> r = read_file_whole(fifo.string());
  writer.join();
  ASSERT_TRUE(r) << r.error().to_string();
  EXPECT_EQ(*r, "[{\"wait\": 1}]");
  fs::remove_all(dir);
}

TEST(ReadFileWhole, ARegularFileOverTheCapIsRefusedWithItsSize) {
  const fs::path dir = test::fresh_temp_dir("read_big");
  std::ofstream(dir / "big.json") << std::string(2000, ' ');
  Result<std::string> r = read_file_whole((dir / "big.json").string(), 1000);
  ASSERT_FALSE(r);
  EXPECT_TRUE(contains(r.error().message, "file is 2000 bytes; at most 1000")) << r.error().message;
  fs::remove_all(dir);
}

TEST(FilePaths, FoldersAndFilesInEachOthersPlaceAreNamed) {
  const fs::path dir = test::fresh_temp_dir("paths");
  std::ofstream(dir / "file.txt") << "x";
  Result<std::string> folder_as_file = read_file_whole(dir.string());
  ASSERT_FALSE(folder_as_file);
  EXPECT_TRUE(contains(folder_as_file.error().message, "is a directory")) << folder_as_file.error().message;

  Status file_as_folder = check_directory((dir / "file.txt").string());
  ASSERT_FALSE(file_as_folder);
  EXPECT_EQ(file_as_folder.error().message, "is not a directory");
  Status missing = check_directory((dir / "none").string());
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().message, "directory does not exist");
  EXPECT_TRUE(check_directory(dir.string()));

  Status out_to_folder = write_file_whole(dir.string(), "x");
  ASSERT_FALSE(out_to_folder);
  EXPECT_TRUE(contains(out_to_folder.error().message, "is a directory, not a file"));
  Status out_under_file = write_file_whole((dir / "file.txt" / "a.json").string(), "x");
  ASSERT_FALSE(out_under_file);
  EXPECT_TRUE(contains(out_under_file.error().message, "file.txt is not a directory")) << out_under_file.error().message;
  Status out_under_missing = write_file_whole((dir / "none" / "a.json").string(), "x");
  ASSERT_FALSE(out_under_missing);
  EXPECT_TRUE(contains(out_under_missing.error().message, "does not exist")) << out_under_missing.error().message;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace penumbra
