#include "util/file_write.h"

#include <filesystem>
#include <fstream>

namespace penumbra {

Status move_into_place(const std::string& tmp, const std::string& path) {
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    Error e = make_error("cannot move the written file into place: " + ec.message());
    e.file = path;
    return e;
  }
  return {};
}

Status write_file_whole(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".partial";
  {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    if (!f) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      Error e = make_error("cannot write the file (does the directory exist and is it writable?)");
      e.file = path;
      return e;
    }
  }
  return move_into_place(tmp, path);
}

}  // namespace penumbra
