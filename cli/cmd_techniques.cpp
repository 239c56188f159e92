// penumbra techniques [NAME...] [--json | --markdown] [--plugin-dir DIR]...: every registered
// technique (or the named ones) with its description and parameters, read from the technique's
// graph JSON (technique::load_technique_graph): the one description the sandbox UI, presets and
// `--set` also use. `--markdown` prints the parameter table a technique's README embeds (a test
// keeps the READMEs equal to it). Needs no GL context.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli/options/args.h"
#include "cli/command.h"
#include "cli/options/plugin_option.h"
#include "technique/technique.h"
#include "techniques/builtin_techniques.h"
#include "passes/shared_passes.h"

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
                      "structural), all read from the technique's graph JSON.",
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
  for (const technique::Technique* technique : selected) {
    const technique::Technique& t = *technique;
    Result<graph::GraphDesc> g = load_technique_graph(registry, t);
    if (!g) {
      std::fprintf(stderr, "penumbra techniques: technique '%s': %s\n%s", t.name.c_str(),
                   g.error().to_string().c_str(), g.error().details.c_str());
      return g.error().exit_code();
    }
    if (markdown) {
      if (selected.size() > 1) std::printf("### %s\n\n%s\n\n", t.name.c_str(), g->description.c_str());
      print_markdown_table(*g);
      if (selected.size() > 1) std::printf("\n");
      continue;
    }
    if (!json) {
      print_text(t, *g);
      continue;
    }
    nlohmann::ordered_json params = nlohmann::ordered_json::array();
    for (const graph::ParamDesc& p : g->parameters) params.push_back(param_json(p));
    all.push_back({{"name", t.name}, {"description", g->description}, {"graph_file", t.graph_file},
                   {"parameters", params}});
  }
  if (json) std::printf("%s\n", all.dump(2).c_str());
  return 0;
}

const CommandRegistration reg{"techniques", "list the shadow techniques and their parameters", cmd_techniques};

}  // namespace
}  // namespace penumbra::cli
