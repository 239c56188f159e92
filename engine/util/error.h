#pragma once
// Errors are values with context: where (file, line, column or JSON pointer), what (pass, slot,
// resource) and a message saying what was expected. Never a bare "invalid input".
//
//   Result<Texture> t = load(...);
//   if (!t) { spdlog::error("{}", t.error().to_string()); return 2; }
//   use(*t);
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace penumbra {

// What kind of failure, so a CLI can map it to the exit-code contract (2 input, 1 internal).
enum class ErrorKind { bad_input, unavailable, internal };

struct Error {
  std::string message;
  std::string file;     // path of the offending file, if any
  int line = 0;         // 1-based, 0 when unknown
  int column = 0;       // 1-based, 0 when unknown
  std::string where;    // pass/slot/resource or JSON pointer, when relevant
  std::string details;  // optional long text (a whole compile log), not part of to_string()
  ErrorKind kind = ErrorKind::bad_input;

  // "file:line:col: where: message" with the empty parts left out.
  std::string to_string() const;
  int exit_code() const { return kind == ErrorKind::internal ? 1 : 2; }
};

Error make_error(std::string message, ErrorKind kind = ErrorKind::bad_input);
// A bad-input error about a file, with the place in it when known ("mesh 2 primitive 0").
Error file_error(std::string file, std::string message, std::string where = {});

// `text` cut to `max` characters with "..." appended: input echoed in a message stays one short
// line whatever the input is.
std::string shortened(std::string_view text, size_t max = 60);

// A value or an Error; deliberately tiny (std::expected is C++23).
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::move(value)) {}
  Result(Error error) : v_(std::move(error)) {}
  explicit operator bool() const { return v_.index() == 0; }
  bool ok() const { return v_.index() == 0; }
  T& value() { return std::get<0>(v_); }
  const T& value() const { return std::get<0>(v_); }
  T& operator*() { return value(); }
  const T& operator*() const { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  const Error& error() const { return std::get<1>(v_); }

 private:
  std::variant<T, Error> v_;
};

// Success or an Error, for operations that produce nothing.
class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(Error error) : error_(std::move(error)) {}
  explicit operator bool() const { return !error_; }
  bool ok() const { return !error_; }
  const Error& error() const { return *error_; }

 private:
  std::optional<Error> error_;
};

}  // namespace penumbra
