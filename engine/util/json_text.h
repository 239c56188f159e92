#pragma once
// What a JSON parser that recurses and keeps the last of two equal keys does not tell us, found
// on the text before it is parsed (nlohmann is used in a few translation units only):
//  - nesting deeper than a limit (a recursive parser would exhaust the stack);
//  - a number that does not fit a 64-bit float (1e999, a 100,000-digit literal), reported at
//    its own line and column with a shortened echo;
//  - an object key given twice (the parser would silently keep only the second value: a second
//    "passes" would wipe the graph).
//
//   if (auto p = scan_json_text(text)) return error_at(p->line, p->column, p->message);
//
// Every JSON the product reads goes through here first, with one depth limit: graphs, presets,
// parameter JSON, sandbox scripts and glTF (whose parser recurses the same way).
#include <optional>
#include <string>
#include <string_view>

namespace penumbra {

// Deepest array/object nesting accepted anywhere. Real files nest under 10 levels (the deepest
// shipped graph: 7); a recursive parser exhausts the stack in the thousands.
inline constexpr int kMaxJsonDepth = 64;

struct JsonTextProblem {
  int line = 1, column = 1;  // 1-based
  std::string message;
};

// Best effort on text that is not JSON at all: the parser then reports the syntax error.
// `duplicate_keys`: false for foreign formats (glTF) whose files we do not own.
std::optional<JsonTextProblem> scan_json_text(std::string_view text, bool duplicate_keys = true);

// 1-based line and column of a byte offset.
void byte_offset_to_line_col(std::string_view text, size_t offset, int& line, int& column);

}  // namespace penumbra
