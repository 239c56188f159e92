// penumbra bench: per-pass median GPU time of techniques on fixed scenes and sizes. On a GPU the
// executor times passes with timestamp queries read a few frames late (no stall); on llvmpipe
// with glFinish + a CPU clock (timer queries do not measure software rendering).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "exec/tile_list_readback.h"
#include "measurement/bench_report.h"
#include "gl/context.h"
#include "measurement/memory_peaks.h"
#include "cli/command.h"
#include "util/file_write.h"
#include "cli/context_option.h"
#include "cli/options/plugin_option.h"
#include "measurement/eval_capture.h"
#include "cli/options/cascade_option.h"
#include "cli/options/scene_option.h"
#include "measurement/reference_frame.h"
#include "measurement/technique_spec.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::cli {
using namespace measurement;  // the measurements this command runs and reports
namespace {

const std::vector<OptionSpec> kSpecs = with_cascade_options(with_scene_options({
    {"techniques", true, false, "a,b:k=v,...", "techniques to time, each with settings of its own "
                                                "(mpg:alteration=pcf); default: every registered one but reference"},
    {"scenes", true, false, "s1,s2", "built-in scenes or glTF files (default colonnade)"},
    {"size", true, false, "WxH,...", "screen sizes in pixels (default 1920x1080); one row per size"},
    {"shadow-size", true, false, "N,...", "shadow-map sizes in texels (default 2048); one row per size"},
    {"frames", true, false, "N", "measured frames per row (default 200, at most 240)"},
    {"warmup", true, false, "N", "frames rendered before measuring (default 10)"},
    {"set", true, true, kAssignmentValueName, "set a parameter of every technique that has it"},
    {"json", true, false, "OUT.json", "write the results as JSON"},
    {"no-peaks", false, false, "", "skip measuring the copy and texture-fetch peaks (GB/s and % of peak stay 0)"},
    context_option_spec(),
    plugin_dir_option_spec(),
}));

int fail(const Error& e) { return report_failure("bench", e); }

struct BenchOptions {
  std::vector<TechniqueSpec> techniques;
  scene::CascadeSettings cascades;
  std::vector<std::string> scenes{"colonnade"}, sets;
  std::vector<std::pair<int, int>> sizes{{1920, 1080}};
  std::vector<int> shadow_sizes{2048};
  int frames = 200, warmup = 10;
  std::string json;
  bool peaks = true;
};

Result<BenchOptions> parse_bench_options(const ParsedArgs& args, const technique::TechniqueRegistry& registry) {
  BenchOptions o;
  if (!args.positionals.empty()) return make_error("unexpected argument '" + args.positionals[0] + "'");
  if (auto t = args.get("techniques")) {
    auto specs = parse_technique_specs("techniques", *t, registry);
    if (!specs) return specs.error();
    o.techniques = *specs;
  } else {
    // The reference is ground truth, not a real-time technique: its per-frame cost depends on
    // how far its accumulation has got. Name it explicitly to time it anyway.
    for (const std::string& n : registry.names())
      if (n != kReferenceTechnique) o.techniques.push_back({n, {}, n});
  }
  Result<scene::CascadeSettings> cascades = parse_cascade_options(args);
  if (!cascades) return cascades.error();
  o.cascades = *cascades;
  if (auto s = args.get("scenes")) {
    auto list = split_list("scenes", *s);
    if (!list) return list.error();
    o.scenes = *list;
  }
  if (auto s = args.get("size")) {
    auto list = split_list("size", *s);
    if (!list) return list.error();
    o.sizes.clear();
    for (const std::string& item : *list) {
      auto size = parse_size("size", item);
      if (!size) return size.error();
      o.sizes.push_back(*size);
    }
  }
  if (auto s = args.get("shadow-size")) {
    auto list = split_list("shadow-size", *s);
    if (!list) return list.error();
    o.shadow_sizes.clear();
    for (const std::string& item : *list) {
      auto n = parse_int("shadow-size", item, 16, 16384);
      if (!n) return n.error();
      o.shadow_sizes.push_back(*n);
    }
  }
  struct IntOption { const char* name; int* value; int lo, hi; };
  for (const IntOption& i : {IntOption{"frames", &o.frames, 1, 240}, IntOption{"warmup", &o.warmup, 0, 100000}})
    if (auto s = args.get(i.name)) {
      auto n = parse_int(i.name, *s, i.lo, i.hi);
      if (!n) return n.error();
      *i.value = *n;
    }
  o.json = args.get("json").value_or("");
  o.peaks = !args.has("no-peaks");
  o.sets = args.all("set");
  if (Status s = check_set_keys(registry, technique_names(o.techniques), o.sets); !s) return s.error();
  return o;
}

Status write_json(const std::string& path, const BenchReport& report) {
  if (Status s = write_file_whole(path, bench_report_json(report)); !s) return s;
  std::printf("wrote %s\n", path.c_str());
  return {};
}

int cmd_bench(const std::vector<std::string>& argv) {
  if (help_requested(argv))
    return print_help("penumbra bench [--techniques a,b:k=v,...] [--scenes s1,s2] [--size WxH,...] [--shadow-size N,...] "
                                    "[--frames N] [--warmup N] [--set k=v]... [--json OUT.json] [--no-peaks]\n"
                                    "                      [--camera C] [--light-dir X,Y,Z] [--light-size S] [--ground on|off]",
                                    "Renders warmup + N frames of each technique on each scene and prints the\n"
                                    "median time of every pass and their sum. On a GPU (EGL) passes are timed with\n"
                                    "timestamp queries; on llvmpipe with glFinish + a CPU clock.\n"
                                    "Beside each time: the bytes the pass moves (the plan's traffic model, as\n"
                                    "`penumbra graph FILE --traffic` prints it), the bandwidth that achieves, and\n"
                                    "its share of the copy peak measured once at the start (a 2 x 512 MiB buffer\n"
                                    "copy on a GPU, 2 x 32 MiB in software), beside a texture-fetch peak.",
                                    kSpecs);
  auto args = parse_args(argv, kSpecs);
  if (!args) return fail(args.error());
  technique::TechniqueRegistry registry;
  if (Status s = register_all_techniques(registry, args->all("plugin-dir")); !s) return fail(s.error());
  auto options = parse_bench_options(*args, registry);
  if (!options) return fail(options.error());
  const BenchOptions& o = *options;
  std::vector<scene::Scene> scenes;
  for (const std::string& s : o.scenes) {
    auto scene = load_scene_option(s, *args, o.sizes.front().first, o.sizes.front().second);  // fitted to the first size
    if (!scene) return fail(scene.error());
    scenes.push_back(std::move(*scene));
  }

  int code = 0;
  auto ctx = open_context(*args, "bench", &code, 16, 16, /*debug_output=*/false);
  if (!ctx) return code;
  exec::PassLibrary library = make_pass_library(registry);
  BenchReport report{ctx->info().backend, ctx->info().renderer, "", {}, {}};
  if (o.peaks) {
    std::fprintf(stderr, "measuring the copy and texture-fetch peaks...\n");
    report.peaks = measure_memory_peaks(/*gpu_timer=*/!gl::current_context_is_software());
    if (!report.peaks.measured)
      std::fprintf(stderr, "penumbra bench: peaks not measured (%s); timing the passes anyway\n",
                   report.peaks.problem.c_str());
  } else {
    report.peaks.problem = "skipped (--no-peaks)";
  }
  const size_t rows = scenes.size() * o.sizes.size() * o.shadow_sizes.size() * o.techniques.size();
  for (const scene::Scene& scene : scenes) {
    technique::TechniqueSession session(registry, library);
    session.set_scene(scene);
    for (const auto& [width, height] : o.sizes) {
      if (Status s = session.resize(width, height); !s) return fail(s.error());
      for (int shadow : o.shadow_sizes) {
        if (Status s = session.set_shadow_size(shadow); !s) return fail(s.error());
        if (Status s = session.set_cascades(o.cascades); !s) return fail(s.error());
        for (const TechniqueSpec& t : o.techniques) {
          std::fprintf(stderr, "[%zu/%zu] bench %s on %s (%dx%d, shadow %d): %d + %d frames...\n",
                       report.rows.size() + 1, rows, t.label.c_str(), scene.name.c_str(), width, height, shadow,
                       o.warmup, o.frames);
          if (Status s = select_technique(session, t, o.sets); !s) return fail(s.error());
          if (Status s = render_timed_frames(session, o.warmup, o.frames); !s) return fail(s.error());
          std::map<std::string, double> tile_fractions;  // the last frame's tile lists, read back
          for (const graph::PlannedPass& p : session.executor().plan().passes)
            if (auto c = exec::dispatched_tiles(session.executor(), p)) tile_fractions[p.name] = c->fraction();
          BenchRow row{t.label, scene.name, width, height, shadow,
                       bench_passes(pass_medians(session, o.frames), session.executor().plan(), tile_fractions),
                       0.0, 0.0};
          summarise_row(row);
          report.rows.push_back(std::move(row));
          report.timing = timing_mode_note(session);
        }
      }
    }
  }
  std::printf("%s", bench_report_table(report).c_str());
  if (!o.json.empty())
    if (Status s = write_json(o.json, report); !s) return fail(s.error());
  return 0;
}

const CommandRegistration reg{"bench", "per-pass median GPU time of techniques on fixed scenes", cmd_bench};

}  // namespace
}  // namespace penumbra::cli
