#include "util/error.h"

namespace penumbra {

std::string Error::to_string() const {
  std::string out;
  if (!file.empty()) {
    out += file;
    if (line > 0) out += ":" + std::to_string(line);
    if (line > 0 && column > 0) out += ":" + std::to_string(column);
    out += ": ";
  }
  if (!where.empty()) out += where + ": ";
  out += message;
  return out;
}

Error make_error(std::string message, ErrorKind kind) {
  Error e;
  e.message = std::move(message);
  e.kind = kind;
  return e;
}

std::string shortened(std::string_view text, size_t max) {
  return text.size() <= max ? std::string(text) : std::string(text.substr(0, max)) + "...";
}

}  // namespace penumbra
