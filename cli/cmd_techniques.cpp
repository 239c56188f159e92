// penumbra techniques [NAME...] [--json | --markdown] [--plugin-dir DIR]...: every registered
// technique (or the named ones) with its description and parameters, read from the technique's
// graph JSON (technique::load_technique_graph): the one description the sandbox UI, presets and
// `--set` also use. `--markdown` prints the parameter table a technique's README embeds (a test
// keeps the READMEs equal to it). Every graph is compiled too (passes/technique_graph_check.h), so
// a broken one is marked, not listed as fine. Needs no GL context.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli/options/args.h"
#include "cli/command.h"
#include "cli/options/plugin_option.h"
#include "technique/technique.h"
#include "techniques/builtin_techniques.h"
#include "passes/shared_passes.h"
#include "passes/technique_graph_check.h"

namespace penumbra::cli {
namespace {

const std::vector<OptionSpec> kSpecs = {
    {"json", false, false, "", "print a JSON array instead of text"},
    {"markdown", false, false, "", "print each technique's parameter table as Markdown (the README tables)"},
    plugin_dir_option_spec(),
};

nlohmann::ordered_json value_json(const graph::ParamValue& v) {
  if (const bool* b = std::get_if<bool>(&v)) return *b;
  if (const int* i = std::get_if<int>(&v)) return *i;
  if (const double* d = std::get_if<double>(&v)) return *d;
  return std::get<std::string>(v);
}

nlohmann::ordered_json param_json(const graph::ParamDesc& p) {
  nlohmann::ordered_json j = {{"name", p.name},
                      {"type", graph::param_type_name(p.type)},
                      {"default", value_json(p.default_value)},
                      {"min", nullptr},
                      {"max", nullptr},
                      {"unit", p.unit},
                      {"description", p.description},
                      {"structural", p.structural}};
  if (p.has_range()) {
    j["min"] = p.min;
    j["max"] = p.max;
  }
  if (p.type == graph::ParamType::enumeration) j["options"] = p.options;
  if (p.has_step()) j["step"] = p.step;
  if (!p.applies.empty()) j["applies"] = p.applies;
  return j;
}

// As typed after --set: enum options unquoted.
std::string default_text(const graph::ParamDesc& p) {
  if (const std::string* s = std::get_if<std::string>(&p.default_value)) return *s;
  return graph::param_value_to_string(p.default_value);
}

// "[1, 64] texels", "box | vogel", "" (unbounded).
std::string range_text(const graph::ParamDesc& p) {
  std::string s;
  if (p.type == graph::ParamType::enumeration) {
    for (const std::string& o : p.options) s += (s.empty() ? "" : " | ") + o;
    return s;
  }
  // Appends, not a chain of operator+ on temporaries: GCC 12 -O2 warns (-Wrestrict) on that chain.
  if (p.has_range()) {
    s.append("[").append(graph::param_value_to_string(p.min)).append(", ");
    s.append(graph::param_value_to_string(p.max)).append("]");
  }
  if (!p.unit.empty()) s.append(s.empty() ? "" : " ").append(p.unit);
  return s;
}

// A Markdown table cell: '|' would end the cell.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

void print_markdown_table(const graph::GraphDesc& g) {
  std::printf("| parameter | type | default | range / options | unit | rebuilds graph | description |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const graph::ParamDesc& p : g.parameters) {
    std::string range;
    if (p.type == graph::ParamType::enumeration)
      for (const std::string& o : p.options) range += (range.empty() ? "" : " / ") + o;
    else if (p.has_range())
      range = graph::param_value_to_string(p.min) + " – " + graph::param_value_to_string(p.max);
    std::printf("| `%s` | %s | %s | %s | %s | %s | %s |\n", p.name.c_str(), graph::param_type_name(p.type),
                cell(default_text(p)).c_str(), cell(range).c_str(), cell(p.unit).c_str(),
                p.structural ? "yes" : "", cell(p.description).c_str());
  }
}

void print_text(const technique::Technique& t, const graph::GraphDesc& g) {
  std::printf("%s\n  %s\n  graph: %s\n", t.name.c_str(), g.description.c_str(), t.graph_file.c_str());
  for (const graph::ParamDesc& p : g.parameters) {
    std::printf("  --set %s=%s\n      %s, %s%s%s\n", p.name.c_str(), default_text(p).c_str(),
                graph::param_type_name(p.type),
                range_text(p).empty() ? "unbounded" : range_text(p).c_str(),
                p.structural ? ", structural (recompiles)" : "",
                p.description.empty() ? "" : (": " + p.description).c_str());
  }
  std::printf("\n");
}

int cmd_techniques(const std::vector<std::string>& argv) {
  if (help_requested(argv))
    return print_help("penumbra techniques [NAME...] [--json | --markdown] [--plugin-dir DIR]...",
                      "Lists every registered shadow technique (or the named ones) with its\n"
                      "description and parameters (type, default, range, unit, description,\n"
                      "structural), all read from the technique's graph JSON. Each graph is also\n"
                      "compiled at its defaults; one that does not compile is marked BROKEN with\n"
                      "its errors (graph_errors in --json) and the exit status is 2.",
                      kSpecs);
  auto args = parse_args(argv, kSpecs);
  if (!args) {
    std::fprintf(stderr, "penumbra techniques: %s\n", args.error().to_string().c_str());
    return 2;
  }
  if (args->has("json") && args->has("markdown")) {
    std::fprintf(stderr, "penumbra techniques: --json and --markdown exclude each other\n");
    return 2;
  }
  technique::TechniqueRegistry registry;
  if (Status s = register_all_techniques(registry, args->all("plugin-dir")); !s) {
    std::fprintf(stderr, "penumbra techniques: %s\n", s.error().to_string().c_str());
    return s.error().exit_code();
  }

  std::vector<const technique::Technique*> selected;
  for (const std::string& name : args->positionals) {
    const technique::Technique* t = registry.find(name);
    if (!t) {
      std::string valid;
      for (const std::string& n : registry.names()) valid += (valid.empty() ? "" : ", ") + n;
      std::fprintf(stderr, "penumbra techniques: unknown technique '%s' (available: %s)\n",
                   shortened(name).c_str(), valid.c_str());
      return 2;
    }
    selected.push_back(t);
  }
  if (selected.empty())
    for (const technique::Technique& t : registry.all()) selected.push_back(&t);

  const bool json = args->has("json"), markdown = args->has("markdown");
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  std::string broken;
  for (const technique::Technique* technique : selected) {
    const technique::Technique& t = *technique;
    // A graph that loads can still fail to compile (a format a slot does not take, a read of a
    // resource nobody writes): such a technique is listed as broken, with why.
    const std::vector<Error> errors = technique_graph_errors(registry, t);
    if (!errors.empty()) broken += (broken.empty() ? "" : ", ") + t.name;
    Result<graph::GraphDesc> g = load_technique_graph(registry, t);
    if (!g || (markdown && !errors.empty())) {
      const Error& e = g ? errors.front() : g.error();
      std::fprintf(stderr, "penumbra techniques: technique '%s': %s\n%s", t.name.c_str(), e.to_string().c_str(),
                   e.details.c_str());
      if (markdown) return e.exit_code();
      if (json) all.push_back({{"name", t.name}, {"graph_file", t.graph_file}, {"graph_errors", {e.to_string()}}});
      else std::printf("%s\n  BROKEN: its graph does not load: %s\n\n", t.name.c_str(), e.to_string().c_str());
      continue;
    }
    if (markdown) {
      if (selected.size() > 1) std::printf("### %s\n\n%s\n\n", t.name.c_str(), g->description.c_str());
      print_markdown_table(*g);
      if (selected.size() > 1) std::printf("\n");
      continue;
    }
    if (!json) {
      print_text(t, *g);
      if (!errors.empty()) {
        std::printf("  BROKEN: its graph does not compile (%zu error%s):\n", errors.size(), errors.size() == 1 ? "" : "s");
        for (const Error& e : errors) std::printf("    %s\n", e.to_string().c_str());
        std::printf("\n");
      }
      continue;
    }
    nlohmann::ordered_json params = nlohmann::ordered_json::array();
    for (const graph::ParamDesc& p : g->parameters) params.push_back(param_json(p));
    nlohmann::ordered_json error_texts = nlohmann::ordered_json::array();
    for (const Error& e : errors) error_texts.push_back(e.to_string());
    all.push_back({{"name", t.name}, {"description", g->description}, {"graph_file", t.graph_file},
                   {"parameters", params}, {"graph_errors", error_texts}});
  }
  if (json) std::printf("%s\n", all.dump(2).c_str());
  if (!broken.empty()) {
    std::fprintf(stderr, "penumbra techniques: these techniques' graphs do not compile: %s\n", broken.c_str());
    return 2;
  }
  return 0;
}

const CommandRegistration reg{"techniques", "list the shadow techniques and their parameters", cmd_techniques};

}  // namespace
}  // namespace penumbra::cli
