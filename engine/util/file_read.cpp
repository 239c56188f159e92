#include "util/file_read.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace penumbra {

Result<std::string> read_file_whole(const std::string& path, std::size_t max_bytes) {
  namespace fs = std::filesystem;
  auto fail = [&](std::string message) {
    Error e = make_error(std::move(message));
    e.file = path;
    return e;
  };
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) return fail("file not found");
  if (fs::is_directory(st)) return fail("is a directory, not a file");
  if (fs::is_regular_file(st)) {
    const auto size = fs::file_size(path, ec);
    if (!ec && size > max_bytes)
      return fail("file is " + std::to_string(size) + " bytes; at most " + std::to_string(max_bytes) + " are read");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot open file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().size() > max_bytes)  // a pipe or device: its size is known only now
    return fail("input is larger than " + std::to_string(max_bytes) + " bytes");
  return text.str();
}

}  // namespace penumbra
