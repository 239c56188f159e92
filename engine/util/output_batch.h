#pragma once
// The outputs of one command run, which appear together or not at all. Each is written to a
// temporary beside its final path; commit() moves them all into place once every one was
// written. A batch destroyed without commit (a later output failed, a render failed) removes
// its temporaries and the folders it created, so a failed run leaves nothing behind and never
// half of a set of files that belong together (eval's heat maps, masks and report). A run stopped
// by SIGINT, SIGTERM or SIGHUP removes them too (util/interrupted_outputs.h).
//
//   OutputBatch out;
//   if (Status s = out.create_directory(dir); !s) return s;
//   if (Status s = write_png(out.staged(dir + "/a.png"), ...); !s) return out.not_written(s.error());
//   if (Status s = out.commit(); !s) return s;
#include <string>
#include <vector>

#include "util/error.h"

namespace penumbra {

class OutputBatch {
 public:
  OutputBatch() = default;
  OutputBatch(const OutputBatch&) = delete;
  OutputBatch& operator=(const OutputBatch&) = delete;
  ~OutputBatch();

  // Creates `dir` and its missing parents; those it created are removed again on failure.
  Status create_directory(const std::string& dir);
  // Where to write the output that will be `path`; checks `path` (check_output_path) first.
  Result<std::string> staged(const std::string& path);
  // Moves every staged output into place. On failure the error names the outputs not written.
  Status commit();
  // `e` with the outputs of this batch that will not be written added to its message.
  Error not_written(Error e) const;

 private:
  void discard();

  void forget_interrupted();

  std::vector<std::pair<std::string, std::string>> staged_;  // temporary, final path
  std::vector<std::string> created_dirs_;                    // outermost first
  std::vector<int> interrupted_handles_;                     // util/interrupted_outputs.h
  bool committed_ = false;
};

}  // namespace penumbra
