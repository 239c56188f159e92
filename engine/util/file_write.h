#pragma once
// Writes a whole file or nothing: the text goes to partial_path(PATH), which is renamed over PATH
// only when every byte was written, so a reader never sees half a report.
#include <string>

#include "util/error.h"

namespace penumbra {

Status write_file_whole(const std::string& path, const std::string& text);

// The name a file is written under before it is moved into place (every writer's temporary).
std::string partial_path(const std::string& path);

// Whether `path` can be an output file, in words that say what is wrong: "is a directory, not a
// file", "its folder DIR does not exist", "DIR is not a directory". Every writer calls it first.
Status check_output_path(const std::string& path);

// Renames a finished temporary file over `path`; on failure removes it. (PNG writers produce
// the temporary themselves.)
Status move_into_place(const std::string& tmp, const std::string& path);

}  // namespace penumbra
