#include "util/error.h"

namespace penumbra {

std::string Error::to_string() const {
  std::string out;
  // The file and the place are often the user's words echoed: each stays short enough for one
  // line (a path keeps its end, where the file's name is).
  constexpr size_t kMaxEchoed = 200;
  if (!file.empty()) {
    out += file.size() > kMaxEchoed ? "..." + file.substr(file.size() - (kMaxEchoed - 3)) : file;
    if (line > 0) out += ":" + std::to_string(line);
    if (line > 0 && column > 0) out += ":" + std::to_string(column);
    out += ": ";
  }
  if (!where.empty()) out += shortened(where, kMaxEchoed) + ": ";
  out += message;
  return out;
}

Error make_error(std::string message, ErrorKind kind) {
  Error e;
  e.message = std::move(message);
  e.kind = kind;
  return e;
}

Error file_error(std::string file, std::string message, std::string where) {
  Error e = make_error(std::move(message));
  e.file = std::move(file);
  e.where = std::move(where);
  return e;
}

std::string shortened(std::string_view text, size_t max) {
  return text.size() <= max ? std::string(text) : std::string(text.substr(0, max)) + "...";
}

}  // namespace penumbra
