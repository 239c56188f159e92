#pragma once
// Minimal option parsing for the subcommands: --name VALUE, --name=VALUE, boolean --flag,
// repeated options (--set k=v ...) and positionals. Unknown options are errors (exit 2).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "util/error.h"

namespace penumbra::cli {

// The value name of a repeated option that takes assignments (--set k=v): parse_args refuses a
// key given twice, which would otherwise silently keep the last value.
inline constexpr const char* kAssignmentValueName = "k=v";

struct OptionSpec {
  std::string name;        // without the leading dashes
  bool takes_value = true;
  bool repeated = false;
  std::string value_name;  // for --help, e.g. "WxH"
  std::string help;
};

struct ParsedArgs {
  std::map<std::string, std::vector<std::string>> values;  // option -> values (flags: {""})
  std::vector<std::string> positionals;
  bool has(const std::string& name) const { return values.count(name) != 0; }
  std::optional<std::string> get(const std::string& name) const;
  std::vector<std::string> all(const std::string& name) const;
};

Result<ParsedArgs> parse_args(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs);

std::string format_help(const std::string& usage, const std::string& description,
                        const std::vector<OptionSpec>& specs);
// --help or -h anywhere on the line (before any parsing, so a bad option does not hide help).
bool help_requested(const std::vector<std::string>& args);
// Prints format_help() to stdout; returns exit code 0.
int print_help(const std::string& usage, const std::string& description, const std::vector<OptionSpec>& specs);

// "640x480" -> {640, 480}; errors name the option and the expected form.
Result<std::pair<int, int>> parse_size(const std::string& option, const std::string& text, int max = 16384);
Result<int> parse_int(const std::string& option, const std::string& text, int lo, int hi);
// A finite number in [lo, hi]; errors name the option and the range.
Result<double> parse_real(const std::string& option, const std::string& text, double lo, double hi);

// Prints "penumbra COMMAND: error" and its details on stderr; returns the error's exit code.
int report_failure(const char* command, const Error& e);

}  // namespace penumbra::cli
