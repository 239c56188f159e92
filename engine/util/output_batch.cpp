#include "util/output_batch.h"

#include <filesystem>

#include "util/file_write.h"
#include "util/interrupted_outputs.h"

namespace penumbra {

namespace fs = std::filesystem;

namespace {

// At most three names of at most 60 characters: the message stays one readable line however many
// outputs a command writes.
std::string file_list(const std::vector<std::string>& paths) {
  constexpr size_t kNames = 3, kChars = 60;
  std::string out;
  for (size_t i = 0; i < paths.size() && i < kNames; ++i) out += (i ? ", " : "") + shortened(paths[i], kChars);
  if (paths.size() > kNames) out += " and " + std::to_string(paths.size() - kNames) + " more";
  return out;
}

}  // namespace

OutputBatch::~OutputBatch() {
  if (!committed_) discard();
}

Status OutputBatch::create_directory(const std::string& dir) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = fs::path(dir); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  fs::create_directories(dir, ec);
  for (auto it = missing.rbegin(); it != missing.rend(); ++it)
    if (fs::is_directory(*it)) {
      created_dirs_.push_back(it->string());
      interrupted_handles_.push_back(interrupted_outputs::remember_directory(it->string()));
    }
  if (ec || !fs::is_directory(dir, ec)) {
    Error e = make_error(fs::exists(dir, ec) ? "is not a directory" : "cannot create the output directory");
    e.file = dir;
    return e;
  }
  return {};
}

Result<std::string> OutputBatch::staged(const std::string& path) {
  if (Status s = check_output_path(path); !s) return s.error();
  std::string tmp = path + ".pending";
  staged_.emplace_back(tmp, path);
  interrupted_handles_.push_back(interrupted_outputs::remember_file(tmp));
  // A stop while the temporary is being written leaves the writer's own temporary (file_write.h).
  interrupted_handles_.push_back(interrupted_outputs::remember_file(partial_path(tmp)));
  return tmp;
}

Status OutputBatch::commit() {
  for (size_t i = 0; i < staged_.size(); ++i) {
    std::error_code ec;
    fs::rename(staged_[i].first, staged_[i].second, ec);
    if (ec) {
      std::vector<std::string> left;
      for (size_t j = i; j < staged_.size(); ++j) left.push_back(staged_[j].second);
      Error e = make_error("cannot move the written file into place (" + ec.message() + "); not written: " +
                           file_list(left));
      e.file = staged_[i].second;
      staged_.erase(staged_.begin(), staged_.begin() + static_cast<std::ptrdiff_t>(i));
      discard();
      committed_ = true;
      return e;
    }
  }
  committed_ = true;
  forget_interrupted();
  return {};
}

void OutputBatch::forget_interrupted() {
  for (int handle : interrupted_handles_) interrupted_outputs::forget(handle);
  interrupted_handles_.clear();
}

Error OutputBatch::not_written(Error e) const {
  std::vector<std::string> paths;
  for (const auto& [tmp, path] : staged_)
    if (path != e.file) paths.push_back(path);
  if (!paths.empty()) e.message += "; so none of the outputs was written (also " + file_list(paths) + ")";
  return e;
}

void OutputBatch::discard() {
  std::error_code ec;
  for (const auto& [tmp, path] : staged_) {
    fs::remove(tmp, ec);
    fs::remove(partial_path(tmp), ec);
  }
  staged_.clear();
  for (auto it = created_dirs_.rbegin(); it != created_dirs_.rend(); ++it)
    if (fs::is_empty(*it, ec)) fs::remove(*it, ec);  // innermost first; a folder holding user files stays
  created_dirs_.clear();
  forget_interrupted();
}

}  // namespace penumbra
