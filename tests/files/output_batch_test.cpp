// OutputBatch: outputs appear together on commit, and a batch given up leaves nothing behind,
// neither its temporaries nor the folders it created, and never touches what was there before.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include "test_support/temp_dir.h"
#include "util/file_write.h"
#include "util/output_batch.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t entries(const fs::path& dir) {
  return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(OutputBatch, NothingAppearsBeforeCommitAndEverythingAfter) {
  const fs::path dir = test::fresh_temp_dir("batch_commit");
  OutputBatch batch;
  ASSERT_TRUE(batch.create_directory((dir / "maps" / "deep").string()));
  for (const fs::path& p : {dir / "maps" / "deep" / "a.txt", dir / "report.json"}) {
    Result<std::string> tmp = batch.staged(p.string());
    ASSERT_TRUE(tmp);
    ASSERT_TRUE(write_file_whole(*tmp, p.filename().string()));
    EXPECT_FALSE(fs::exists(p));
  }
  ASSERT_TRUE(batch.commit());
  EXPECT_EQ(read(dir / "maps" / "deep" / "a.txt"), "a.txt");
  EXPECT_EQ(read(dir / "report.json"), "report.json");
  EXPECT_EQ(entries(dir / "maps" / "deep"), 1u);  // no temporary left
  EXPECT_EQ(entries(dir), 2u);
  fs::remove_all(dir);
}

TEST(OutputBatch, ABatchGivenUpLeavesNothingItMadeAndKeepsWhatWasThere) {
  const fs::path dir = test::fresh_temp_dir("batch_discard");
  std::ofstream(dir / "old.json") << "the user's";
  fs::create_directories(dir / "mine");
  std::ofstream(dir / "mine" / "keep.txt") << "keep";
  {
    OutputBatch batch;
    ASSERT_TRUE(batch.create_directory((dir / "new" / "deeper").string()));
    ASSERT_TRUE(batch.create_directory((dir / "mine").string()));
    for (const fs::path& p : {dir / "new" / "deeper" / "a.png", dir / "mine" / "b.png", dir / "old.json"}) {
      Result<std::string> tmp = batch.staged(p.string());
      ASSERT_TRUE(tmp);
      ASSERT_TRUE(write_file_whole(*tmp, "new"));
    }
    // A later output into a place that cannot hold it: the command gives the batch up.
    Result<std::string> bad = batch.staged(dir.string());
    ASSERT_FALSE(bad);
    const Error e = batch.not_written(bad.error());
    EXPECT_NE(e.message.find("none of the outputs was written"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("a.png"), std::string::npos) << e.message;
  }
  EXPECT_FALSE(fs::exists(dir / "new"));
  EXPECT_EQ(read(dir / "old.json"), "the user's");
  EXPECT_EQ(entries(dir / "mine"), 1u);
  EXPECT_EQ(entries(dir), 2u);
  fs::remove_all(dir);
}

// However many outputs a command stages, the message names at most three (each at most 60
// characters) and counts the rest, so it stays one line.
TEST(OutputBatch, TheListOfOutputsNotWrittenStaysShort) {
  const fs::path dir = test::fresh_temp_dir("batch_many");
  OutputBatch batch;
  const std::string long_name(120, 'n');
  for (int i = 0; i < 7; ++i) {
    Result<std::string> tmp = batch.staged((dir / (long_name + std::to_string(i) + ".png")).string());
    ASSERT_TRUE(tmp);
    ASSERT_TRUE(write_file_whole(*tmp, "x"));
  }
  const Error e = batch.not_written(make_error("the last output failed"));
  EXPECT_NE(e.message.find("and 4 more"), std::string::npos) << e.message;
  EXPECT_LT(e.message.size(), 300u) << e.message;
  fs::remove_all(dir);
}

TEST(OutputBatch, AFileWhereTheFolderBelongsIsNamed) {
  const fs::path dir = test::fresh_temp_dir("batch_file_as_dir");
  std::ofstream(dir / "maps") << "x";
  OutputBatch batch;
  Status s = batch.create_directory((dir / "maps").string());
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().message, "is not a directory");
  fs::remove_all(dir);
}

// A run stopped while an output is being written: the writer's own temporary (partial_path) exists
// and the staged name does not yet. The stop signal removes both, the finished outputs' staged
// files and the folder (util/interrupted_outputs.h); the process ends by the signal itself. In a
// child process, which the signal ends.
TEST(OutputBatch, AStopWhileAnOutputIsBeingWrittenLeavesNothing) {
  const fs::path dir = test::fresh_temp_dir("batch_stopped") / "out";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    OutputBatch batch;
    if (!batch.create_directory(dir.string())) _exit(3);
    Result<std::string> done = batch.staged((dir / "a.png").string());
    Result<std::string> writing = batch.staged((dir / "b.png").string());
    if (!done || !writing || !write_file_whole(*done, "a")) _exit(4);
    std::ofstream(partial_path(*writing)) << "half of b";
    raise(SIGTERM);
    _exit(5);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the child exited with " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_FALSE(fs::exists(dir)) << "left behind: " << (fs::exists(dir) ? entries(dir) : 0) << " entries in " << dir;
}

}  // namespace
}  // namespace penumbra
