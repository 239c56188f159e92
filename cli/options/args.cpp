#include "cli/options/args.h"

#include "graph/parameters.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace penumbra::cli {

std::optional<std::string> ParsedArgs::get(const std::string& name) const {
  auto it = values.find(name);
  if (it == values.end() || it->second.empty()) return std::nullopt;
  return it->second.back();
}

std::vector<std::string> ParsedArgs::all(const std::string& name) const {
  auto it = values.find(name);
  return it == values.end() ? std::vector<std::string>{} : it->second;
}

Result<ParsedArgs> parse_args(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs) {
  ParsedArgs out;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() < 2 || a.rfind("--", 0) != 0) {
      out.positionals.push_back(a);
      continue;
    }
    std::string name = a.substr(2), value;
    bool inline_value = false;
    if (auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      inline_value = true;
    }
    const OptionSpec* spec = nullptr;
    for (const OptionSpec& s : specs)
      if (s.name == name) spec = &s;
    if (!spec) return make_error("unknown option --" + shortened(name) + " (see --help)");
    if (spec->takes_value && !inline_value) {
      if (i + 1 >= args.size()) return make_error("option --" + name + " needs a value" +
                                                  (spec->value_name.empty() ? "" : " (" + spec->value_name + ")"));
      // "--size --context osmesa": the value is missing, not "--context".
      if (args[i + 1].rfind("--", 0) == 0 && args[i + 1].size() > 2)
        return make_error("option --" + name + " needs a value" +
                          (spec->value_name.empty() ? "" : " (" + spec->value_name + ")") + ", got option " +
                          shortened(args[i + 1]));
      value = args[++i];
    }
    if (!spec->takes_value && inline_value) return make_error("option --" + name + " takes no value");
    auto& slot = out.values[name];
    if (!spec->repeated && !slot.empty()) return make_error("option --" + name + " given twice");
    slot.push_back(value);
  }
  for (const OptionSpec& spec : specs)
    if (spec.repeated && spec.value_name == kAssignmentValueName && out.has(spec.name))
      if (Status s = graph::check_assignment_keys("--" + spec.name, out.all(spec.name)); !s) return s.error();
  return out;
}


std::string format_help(const std::string& usage, const std::string& description,
                        const std::vector<OptionSpec>& specs) {
  std::string out = "usage: " + usage + "\n\n" + description + "\n";
  if (!specs.empty()) out += "\noptions:\n";
  for (const OptionSpec& s : specs) {
    std::string left = "  --" + s.name + (s.takes_value ? " " + (s.value_name.empty() ? "VALUE" : s.value_name) : "");
    if (left.size() < 28) left.resize(28, ' ');
    else left += "\n" + std::string(28, ' ');
    out += left + s.help + (s.repeated ? " (repeatable)" : "") + "\n";
  }
  out += "  --help                    show this help\n";
  return out;
}

bool help_requested(const std::vector<std::string>& args) {
  for (const std::string& a : args)
    if (a == "--help" || a == "-h") return true;
  return false;
}

int print_help(const std::string& usage, const std::string& description, const std::vector<OptionSpec>& specs) {
  std::fputs(format_help(usage, description, specs).c_str(), stdout);
  return 0;
}

Result<int> parse_int(const std::string& option, const std::string& text, int lo, int hi) {
  int v = 0;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size() || v < lo || v > hi)
    return make_error("--" + option + " expects an integer in [" + std::to_string(lo) + ", " +
                      std::to_string(hi) + "], got '" + shortened(text) + "'");
  return v;
}

Result<double> parse_real(const std::string& option, const std::string& text, double lo, double hi) {
  char* end = nullptr;
  const double v = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v) || v < lo || v > hi) {
    std::ostringstream m;
    m << "--" << option << " expects a number in [" << lo << ", " << hi << "], got '" << shortened(text) << "'";
    return make_error(m.str());
  }
  return v;
}

Result<std::pair<int, int>> parse_size(const std::string& option, const std::string& text, int max) {
  auto x = text.find('x');
  if (x == std::string::npos) return make_error("--" + option + " expects WxH (e.g. 640x360), got '" + shortened(text) + "'");
  auto w = parse_int(option, text.substr(0, x), 1, max);
  auto h = parse_int(option, text.substr(x + 1), 1, max);
  if (!w || !h) return make_error("--" + option + " expects WxH with each side in [1, " + std::to_string(max) +
                                  "], got '" + shortened(text) + "'");
  return std::pair{*w, *h};
}

int report_failure(const char* command, const Error& e) {
  std::fprintf(stderr, "penumbra %s: %s\n", command, e.to_string().c_str());
  if (!e.details.empty()) std::fprintf(stderr, "%s", e.details.c_str());
  return e.exit_code();
}

}  // namespace penumbra::cli
