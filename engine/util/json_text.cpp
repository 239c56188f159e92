#include "util/json_text.h"

#include "util/error.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <unordered_map>
#include <vector>

namespace penumbra {

namespace {

// Longest number literal accepted: a double needs at most 17 significant digits, and a longer
// literal is almost surely hostile or a typo.
constexpr size_t kMaxNumberLength = 64;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

struct Frame {
  bool object = false;
  std::unordered_map<std::string_view, size_t> keys;  // raw key text -> offset of its quote
};

class Scanner {
 public:
  Scanner(std::string_view text, bool duplicate_keys) : text_(text), duplicate_keys_(duplicate_keys) {}

  std::optional<JsonTextProblem> run() {
    while (pos_ < text_.size()) {
      char c = text_[pos_];
      if (c == '"') {
        if (auto p = string_token()) return p;
      } else if (c == '{' || c == '[') {
        if (static_cast<int>(stack_.size()) >= kMaxJsonDepth)
          return problem(pos_, "nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        stack_.push_back(Frame{c == '{', {}});
        ++pos_;
      } else if (c == '}' || c == ']') {
        if (!stack_.empty()) stack_.pop_back();
        ++pos_;
      } else if (c == '-' || std::isdigit(static_cast<unsigned char>(c))) {
        if (auto p = number_token()) return p;
      } else {
        ++pos_;
      }
    }
    return std::nullopt;
  }

 private:
  JsonTextProblem problem(size_t offset, std::string message) const {
    JsonTextProblem p;
    byte_offset_to_line_col(text_, offset, p.line, p.column);
    p.message = std::move(message);
    return p;
  }

  std::optional<JsonTextProblem> string_token() {
    size_t start = pos_++;
    while (pos_ < text_.size() && text_[pos_] != '"') pos_ += text_[pos_] == '\\' ? 2 : 1;
    size_t end = std::min(pos_, text_.size());
    ++pos_;
    size_t next = pos_;
    while (next < text_.size() && is_space(text_[next])) ++next;
    bool is_key = next < text_.size() && text_[next] == ':' && !stack_.empty() && stack_.back().object;
    if (!is_key || !duplicate_keys_) return std::nullopt;
    std::string_view key = text_.substr(start + 1, end - start - 1);
    auto [it, inserted] = stack_.back().keys.emplace(key, start);
    if (inserted) return std::nullopt;
    int line = 0, column = 0;
    byte_offset_to_line_col(text_, it->second, line, column);
    return problem(start, "duplicate key \"" + shortened(key) + "\" (first at " + std::to_string(line) +
                              ":" + std::to_string(column) +
                              "); JSON parsers keep only the last value, so the first would be lost");
  }

  std::optional<JsonTextProblem> number_token() {
    size_t start = pos_;
    while (pos_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[pos_])) ||
                                   text_[pos_] == '-' || text_[pos_] == '+' || text_[pos_] == '.' ||
                                   text_[pos_] == 'e' || text_[pos_] == 'E'))
      ++pos_;
    std::string_view token = text_.substr(start, pos_ - start);
    if (token.size() > kMaxNumberLength)
      return problem(start, "number " + shortened(token, 24) + " has " + std::to_string(token.size()) +
                                " characters; at most " + std::to_string(kMaxNumberLength));
    std::string copy(token);
    double v = std::strtod(copy.c_str(), nullptr);
    if (!std::isfinite(v))
      return problem(start, "number " + shortened(token, 24) + " does not fit a 64-bit float");
    return std::nullopt;
  }

  std::string_view text_;
  bool duplicate_keys_;
  size_t pos_ = 0;
  std::vector<Frame> stack_;
};

}  // namespace

std::optional<JsonTextProblem> scan_json_text(std::string_view text, bool duplicate_keys) {
  return Scanner(text, duplicate_keys).run();
}

void byte_offset_to_line_col(std::string_view text, size_t offset, int& line, int& column) {
  line = 1;
  column = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
}

}  // namespace penumbra
