// `penumbra graph`: compile a graph file and print its plan (see cmd_graph.h).
#include "cmd_graph.h"

#include <charconv>
#include <exception>
#include <iostream>

#include "graph/compiler.h"
#include "graph/exposures.h"
#include "graph/graph_json.h"
#include "cli/command.h"
#include "cli/options/args.h"
#include "pass_registry.h"
#include "technique/frame_graph.h"
#include "util/file_write.h"
#include "util/output_batch.h"

namespace penumbra::cli {

namespace {

const char* kHelp =
    "usage: penumbra graph FILE.json [--plan] [--traffic] [--json OUT.json] [--dot OUT.dot]\n"
    "                      [--screen WxH] [--shadow N]\n"
    "       penumbra graph --pass-types\n"
    "                      [--set k=v]... [--no-reuse] [--extended-lifetimes] [--frame | --no-frame]\n"
    "                      [--plugin-dir DIR]...\n"
    "Compiles a render-graph file (docs/graph-format.md) against every built-in pass type (and\n"
    "those of the plugins loaded) and reports errors or the plan. A technique graph (one that reads the frame's scene, camera,\n"
    "light or gbuffer_* without declaring them) is composed into the frame it runs in first.\n"
    "  --plan                print the compiled plan (order, culled, textures, lifetimes,\n"
    "                        barriers, memory)\n"
    "  --traffic             print the bytes every pass reads and writes per execution\n"
    "                        (each bound texture once at its size; docs/graph-format.md,\n"
    "                        \"Traffic\"), in MB and bytes per screen pixel\n"
    "  --json OUT.json       write the plan as JSON (passes, bindings, parameters, traffic,\n"
    "                        physical resources, memory)\n"
    "  --dot OUT.dot         write the plan as Graphviz (pass boxes show their traffic)\n"
    "  --screen WxH          screen size in pixels (default 1920x1080)\n"
    "  --shadow N            shadow map size in texels (default 2048)\n"
    "  --set k=v             set a graph parameter (repeatable)\n"
    "  --no-reuse            debug: one texture per resource\n"
    "  --extended-lifetimes  debug: every transient lives the whole frame\n"
    "  --frame               always compose into the frame (G-buffer prologue, lighting\n"
    "                        epilogue; docs/writing-a-technique.md)\n"
    "  --no-frame            never compose: compile the file as it is\n"
    "  --pass-types          list every registered pass type with its slots and parameters\n"
    "  --plugin-dir DIR      also load technique plugins from DIR (repeatable); then from\n"
    "                        PENUMBRA_PLUGIN_PATH (colon-separated)\n"
    "Exit codes: 0 ok, 2 invalid input, 1 internal error.\n";

int usage_error(const std::string& message) {
  std::cerr << "penumbra graph: " << message << " (see --help)\n";
  return 2;
}

// What a graph file can use: every pass type with its slots (access, usage, formats) and
// parameters (type, default, range).
int print_pass_types(const graph::PassTypeRegistry& registry) {
  for (const std::string& name : registry.names()) {
    const graph::PassTypeDecl& t = *registry.find(name);
    std::cout << name << (t.side_effect ? " (side effect)" : "") << "\n  " << t.description << "\n";
    for (const graph::SlotDecl& slot : t.slots) {
      std::cout << "  slot  " << slot.name << ": " << graph::access_name(slot.access) << " "
                << graph::slot_kind_name(slot.kind) << ", " << graph::usage_name(slot.usage);
      if (!slot.formats.empty()) {
        std::cout << ", ";
        for (size_t i = 0; i < slot.formats.size(); ++i) std::cout << (i ? "|" : "") << graph::format_name(slot.formats[i]);
      }
      std::cout << (slot.ping_pong ? ", ping-pong (writes into the texture of the version two back)" : "")
                << (slot.required ? "" : " (optional)") << "\n";
    }
    for (const graph::ParamDesc& d : t.params) {
      std::cout << "  param " << d.name << ": " << graph::param_type_name(d.type) << " = "
                << graph::param_value_to_string(d.default_value);
      if (d.has_range()) std::cout << " in [" << d.min << ", " << d.max << "]";
      if (!d.options.empty()) {
        std::cout << " of ";
        for (size_t i = 0; i < d.options.size(); ++i) std::cout << (i ? "|" : "") << d.options[i];
      }
      if (!d.unit.empty()) std::cout << " " << d.unit;
      std::cout << "\n";
    }
  }
  return 0;
}

bool parse_positive(std::string_view text, int& out, int max) {
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc{} && p == text.data() + text.size() && out >= 1 && out <= max;
}

int run(const std::vector<std::string>& args) {
  std::string file, dot_path, json_path;
  bool print_plan = false, print_traffic = false, frame = false, no_frame = false;
  graph::CompileSettings settings;
  graph::CompileOptions options;
  std::vector<std::string> sets, plugin_dirs;
  bool pass_types = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= args.size()) return false;
      out = args[++i];
      return true;
    };
    std::string v;
    if (a == "--help" || a == "-h") {
      std::cout << kHelp;
      return 0;
    } else if (a == "--pass-types") {
      pass_types = true;
    } else if (a == "--plugin-dir") {
      if (!value(v)) return usage_error("--plugin-dir needs DIR");
      plugin_dirs.push_back(v);
    } else if (a == "--plan") {
      print_plan = true;
    } else if (a == "--traffic") {
      print_traffic = true;
    } else if (a == "--json") {
      if (!value(json_path)) return usage_error("--json needs OUT.json");
    } else if (a == "--frame") {
      frame = true;
    } else if (a == "--no-frame") {
      no_frame = true;
    } else if (a == "--no-reuse") {
      options.no_reuse = true;
    } else if (a == "--extended-lifetimes") {
      options.extended_lifetimes = true;
    } else if (a == "--dot") {
      if (!value(dot_path)) return usage_error("--dot needs OUT.dot");
    } else if (a == "--set") {
      if (!value(v)) return usage_error("--set needs k=v");
      sets.push_back(v);
    } else if (a == "--shadow") {
      if (!value(v) || !parse_positive(v, settings.shadow_size, 16384))
        return usage_error("--shadow expects an integer in 1..16384 (texels)");
    } else if (a == "--screen") {
      size_t x = value(v) ? v.find('x') : std::string::npos;
      if (x == std::string::npos ||
          !parse_positive(std::string_view(v).substr(0, x), settings.screen_w, 16384) ||
          !parse_positive(std::string_view(v).substr(x + 1), settings.screen_h, 16384))
        return usage_error("--screen expects WxH, e.g. 1280x720");
    } else if (!a.empty() && a[0] == '-') {
      return usage_error("unknown option '" + shortened(a) + "'");
    } else if (file.empty()) {
      file = a;
    } else {
      return usage_error("one graph file expected, got also '" + shortened(a) + "'");
    }
  }
  auto library = cli_pass_library(plugin_dirs);
  if (!library) {
    std::cerr << "penumbra graph: " << library.error().to_string() << "\n";
    return library.error().exit_code();
  }
  if (pass_types) return print_pass_types(library->declarations());
  if (file.empty()) return usage_error("missing FILE.json");
  if (Status st = graph::check_assignment_keys("--set", sets); !st) return usage_error(st.error().to_string());
  if (frame && no_frame) return usage_error("--frame and --no-frame exclude each other");

  graph::Checked<graph::GraphDesc> desc = graph::load_graph_json(file);
  if (!desc) {
    for (const auto& e : desc.errors()) std::cerr << e.to_string() << "\n";
    return 2;
  }
  if (graph::GraphErrors errors = graph::resolve_exposures(*desc, library->declarations()); !errors.empty()) {
    for (const auto& e : errors) std::cerr << e.to_string() << "\n";
    return 2;
  }
  const bool compose = frame || (!no_frame && technique::reads_frame_resources(*desc));
  if (compose) {
    auto composed = technique::compose_frame_graph(*desc);
    if (!composed) {
      std::cerr << composed.error().to_string() << "\n";
      return 2;
    }
    *desc = std::move(*composed);
  }
  graph::ParameterSet params(desc->parameters);
  for (const auto& s : sets) {
    if (Status st = params.set_from_string(s); !st) {
      std::cerr << file << ": --set " << shortened(s) << ": " << st.error().message << "\n";
      return 2;
    }
  }
  auto plan = graph::compile(*desc, library->declarations(), params, settings, options);
  if (!plan) {
    for (const auto& e : plan.errors()) std::cerr << e.to_string() << "\n";
    return 2;
  }
  OutputBatch outputs;  // --dot and --json together or neither
  for (const auto& [path, text] : {std::pair{dot_path, graph::to_dot(*plan)}, std::pair{json_path, graph::to_json(*plan)}}) {
    if (path.empty()) continue;
    Result<std::string> tmp = outputs.staged(path);
    Status st = tmp ? write_file_whole(*tmp, text) : Status(tmp.error());
    if (!st) {
      Error e = st.error();
      e.file = path;
      e = outputs.not_written(e);
      std::cerr << "penumbra graph: " << e.to_string() << "\n";
      return e.exit_code();
    }
  }
  if (Status st = outputs.commit(); !st) {
    std::cerr << "penumbra graph: " << st.error().to_string() << "\n";
    return st.error().exit_code();
  }
  if (print_plan) std::cout << graph::to_text(*plan);
  if (print_traffic) std::cout << graph::traffic_table(*plan);
  if (!print_plan && !print_traffic)
    std::cout << file << ": ok" << (compose ? " (composed into the frame)" : "") << ", " << plan->passes.size() << " passes, " << plan->culled.size()
              << " culled, " << plan->physical.size() << " physical resources, "
              << plan->memory.assigned_bytes << " of " << plan->memory.naive_bytes << " B\n";
  return 0;
}

}  // namespace

namespace {
const CommandRegistration reg{"graph", "compile a render-graph JSON file, print the plan or dot", cmd_graph};
}  // namespace

int cmd_graph(const std::vector<std::string>& args) {
  try {
    return run(args);
  } catch (const std::exception& e) {
    std::cerr << "penumbra graph: internal error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace penumbra::cli
