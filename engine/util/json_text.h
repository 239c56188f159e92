#pragma once
// What a JSON parser that recurses and keeps the last of two equal keys does not tell us, found
// on the text before it is parsed (nlohmann is used in a few translation units only):
//  - nesting deeper than a limit (a recursive parser would exhaust the stack);
//  - a number that does not fit a 64-bit float (1e999, a 100,000-digit literal), reported at
//    its own line and column with a shortened echo;
//  - an object key given twice (the parser would silently keep only the second value: a second
//    "passes" would wipe the graph).
//
//   if (auto p = scan_json_text(text, 256)) return error_at(p->line, p->column, p->message);
#include <optional>
#include <string>
#include <string_view>

namespace penumbra {

struct JsonTextProblem {
  int line = 1, column = 1;  // 1-based
  std::string message;
};

// Best effort on text that is not JSON at all: the parser then reports the syntax error.
std::optional<JsonTextProblem> scan_json_text(std::string_view text, int max_depth);

// 1-based line and column of a byte offset.
void byte_offset_to_line_col(std::string_view text, size_t offset, int& line, int& column);

}  // namespace penumbra
