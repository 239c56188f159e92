#include "util/file_write.h"

#include <filesystem>
#include <fstream>

namespace penumbra {

std::string partial_path(const std::string& path) { return path + ".partial"; }

Status move_into_place(const std::string& tmp, const std::string& path) {
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    return file_error(path, "cannot move the written file into place: " + ec.message());
  }
  return {};
}

Status check_output_path(const std::string& path) {
  namespace fs = std::filesystem;
  auto fail = [&](std::string message) { return file_error(path, std::move(message)); };
  std::error_code ec;
  if (fs::is_directory(path, ec)) return fail("is a directory, not a file");
  const fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) return {};
  const fs::file_status st = fs::status(parent, ec);
  if (!fs::exists(st)) return fail("its folder " + shortened(parent.string(), 200) + " does not exist");
  if (!fs::is_directory(st)) return fail(shortened(parent.string(), 200) + " is not a directory");
  return {};
}

Status write_file_whole(const std::string& path, const std::string& text) {
  if (Status s = check_output_path(path); !s) return s;
  const std::string tmp = partial_path(path);
  {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    if (!f) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      return file_error(path, "cannot write the file (does the directory exist and is it writable?)");
    }
  }
  return move_into_place(tmp, path);
}

}  // namespace penumbra
