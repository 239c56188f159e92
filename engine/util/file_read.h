#pragma once
// Reads a whole input file (graph JSON, sandbox script, preset), with the errors a user needs:
// not found, a directory, unreadable, or larger than the limit for that kind of file.
//
//   Result<std::string> text = read_file_whole(path, kMaxScriptBytes);
#include <cstddef>
#include <string>

#include "util/error.h"

namespace penumbra {

// 16 MiB: far larger than any graph, script or preset a person writes; a bigger file is a
// mistake (a binary, a log) and is refused before it is read.
inline constexpr std::size_t kMaxInputFileBytes = 16u << 20;

Result<std::string> read_file_whole(const std::string& path, std::size_t max_bytes = kMaxInputFileBytes);

// A folder the user named (plugins, outputs): "does not exist" or "is not a directory" (a file
// given where a folder belongs), with the path as the error's file.
Status check_directory(const std::string& path);

}  // namespace penumbra
