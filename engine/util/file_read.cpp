#include "util/file_read.h"

#include <filesystem>
#include <fstream>

namespace penumbra {

namespace {

// What a path is when it is not a regular file, in the words `ls -l` users know.
const char* kind_of_special_file(const std::filesystem::file_status& st) {
  namespace fs = std::filesystem;
  if (fs::is_character_file(st)) return "a character device";
  if (fs::is_block_file(st)) return "a block device";
  if (fs::is_socket(st)) return "a socket";
  return nullptr;
}

}  // namespace

Result<std::string> read_file_whole(const std::string& path, std::size_t max_bytes) {
  namespace fs = std::filesystem;
  auto fail = [&](std::string message) { return file_error(path, std::move(message)); };
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) return fail("file not found");
  if (fs::is_directory(st)) return fail("is a directory, not a file");
  // /dev/zero never ends and /dev/urandom neither: refused before a byte is read. A pipe
  // (`--script <(generate)`) is read, up to the cap.
  if (const char* kind = kind_of_special_file(st)) return fail(std::string("is ") + kind + ", not a regular file");
  if (fs::is_regular_file(st)) {
    const auto size = fs::file_size(path, ec);
    if (!ec && size > max_bytes)
      return fail("file is " + std::to_string(size) + " bytes; at most " + std::to_string(max_bytes) + " are read");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot open file for reading");
  // Read in chunks and stop one byte past the cap: a file that grows while read, or a pipe
  // that never closes, costs at most the cap in memory.
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<size_t>(in.gcount()));
    if (text.size() > max_bytes)
      return fail("input is larger than " + std::to_string(max_bytes) + " bytes (the cap for this kind of file)");
  }
  if (in.bad()) return fail("read error");
  return text;
}

Status check_directory(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (fs::is_directory(st)) return {};
  return file_error(path, fs::exists(st) ? "is not a directory" : "directory does not exist");
}

}  // namespace penumbra
