// penumbra eval: each technique's shadow_mask against a ground-truth reference of the same frame
// (same scene, camera, light, size), over receiver pixels, plus the technique's GPU time.
// Everything is computed before anything is written, so bad input or a failure leaves no
// partial JSON or heat map behind.
#include <chrono>
#include <cstdio>
#include <optional>
#include <filesystem>
#include <fstream>

#include "cli/command.h"
#include "util/file_write.h"
#include "cli/context_option.h"
#include "cli/eval_capture.h"
#include "cli/eval_report.h"
#include "cli/scene_option.h"
#include "cli/technique_spec.h"
#include "metrics/heat_map.h"
#include "plugin/frame_graph.h"
#include "techniques/builtin_techniques.h"
#include "techniques/reference/reference_progress.h"

namespace penumbra::cli {
namespace {

// Heat maps show |technique - reference| / kHeatMapScale (white at 0.25 and above).
constexpr float kHeatMapScale = 0.25f;

const std::vector<OptionSpec> kSpecs = with_scene_options({
    {"scene", true, false, "NAME|FILE", "built-in scene (fence, ball, poles, colonnade, palms, showcase) or .gltf/.glb"},
    {"techniques", true, false, "a,b:k=v,...", "techniques to evaluate, each with settings of its own (pmchss:variant=regular:k=2)"},
    {"reference", true, false, "raytraced|raster", "ground truth method (default raytraced)"},
    {"size", true, false, "WxH", "image size in pixels (default 640x360)"},
    {"shadow-size", true, false, "N", "techniques' shadow-map size in texels (default 2048)"},
    {"rays", true, false, "M", "raytraced reference: rays per pixel (default 256)"},
    {"samples", true, false, "N", "raster reference: light sample points / shadow maps (default 1024)"},
    {"frames", true, false, "N", "measured frames per technique for the median time (default 10)"},
    {"json", true, false, "OUT.json", "write the results as JSON"},
    {"heatmaps", true, false, "DIR", "write one error heat-map PNG per technique into DIR"},
    {"set", true, true, "k=v", "set a parameter of every listed technique (and the reference) that has it"},
    context_option_spec(),
});

constexpr int kWarmupFrames = 3;

int fail(const Error& e) {
  std::fprintf(stderr, "penumbra eval: %s\n", e.to_string().c_str());
  if (!e.details.empty()) std::fprintf(stderr, "%s", e.details.c_str());
  return e.exit_code();
}

struct EvalOptions {
  std::string scene_name;
  std::vector<TechniqueSpec> techniques;
  std::string reference = "raytraced";
  int width = 640, height = 360, shadow = 2048, rays = 256, samples = 1024, frames = 10;
  std::string json, heatmaps;
  std::vector<std::string> sets;
};

Result<EvalOptions> parse_eval_options(const ParsedArgs& args, const plugin::TechniqueRegistry& registry) {
  EvalOptions o;
  if (!args.positionals.empty()) return make_error("unexpected argument '" + args.positionals[0] + "'");
  if (!args.get("scene")) return make_error("--scene NAME|FILE is required");
  o.scene_name = *args.get("scene");
  if (!args.get("techniques")) return make_error("--techniques a,b,c is required");
  auto specs = parse_technique_specs("techniques", *args.get("techniques"), registry);
  if (!specs) return specs.error();
  o.techniques = *specs;
  if (auto r = args.get("reference")) {
    if (*r != "raytraced" && *r != "raster")
      return make_error("--reference expects raytraced or raster, got '" + *r + "'");
    o.reference = *r;
  }
  if (auto s = args.get("size")) {
    auto size = parse_size("size", *s);
    if (!size) return size.error();
    std::tie(o.width, o.height) = *size;
  }
  struct IntOption { const char* name; int* value; int lo, hi; };
  for (const IntOption& i : {IntOption{"shadow-size", &o.shadow, 16, 16384}, IntOption{"rays", &o.rays, 1, 65536},
                             IntOption{"samples", &o.samples, 1, 65536}, IntOption{"frames", &o.frames, 1, 240}})
    if (auto s = args.get(i.name)) {
      auto n = parse_int(i.name, *s, i.lo, i.hi);
      if (!n) return n.error();
      *i.value = *n;
    }
  o.json = args.get("json").value_or("");
  o.heatmaps = args.get("heatmaps").value_or("");
  o.sets = args.all("set");
  std::vector<std::string> with_reference = technique_names(o.techniques);
  with_reference.push_back("reference");
  if (Status s = check_set_keys(registry, with_reference, o.sets); !s) return s.error();
  return o;
}

// Renders the reference to completion: raster accumulates until all samples are in (progress
// every ~10%), raytraced traces once (the pass logs its own progress).
Status render_reference(plugin::TechniqueSession& session, const EvalOptions& o) {
  if (Status s = session.set_technique("reference"); !s) return s;
  if (Status s = apply_matching_sets(session, o.sets); !s) return s;
  for (const std::string& kv : {"method=" + o.reference, "rays=" + std::to_string(o.rays),
                                "samples=" + std::to_string(o.samples)})
    if (Status s = session.set_param(kv); !s) return s;
  const int per_frame = std::max(1, session.params().get_int("maps_per_frame"));
  const int max_frames = o.reference == "raster" ? (o.samples + per_frame - 1) / per_frame + 2 : 1;
  int next_report = 1;
  for (int f = 0; f < max_frames; ++f) {
    if (Status s = session.render(); !s) return s;
    const reference::ReferenceProgress p = reference::reference_progress();
    if (o.reference == "raster" && p.fraction() * 10.0 >= next_report) {
      std::fprintf(stderr, "reference (raster): %lld/%lld shadow maps\n", static_cast<long long>(p.done),
                   static_cast<long long>(p.total));
      next_report = static_cast<int>(p.fraction() * 10.0) + 1;
    }
    if (p.complete()) return {};
  }
  return make_error("the reference did not complete in " + std::to_string(max_frames) + " frames", ErrorKind::internal);
}

// Renders one technique (a listed `reference` runs to completion first) and compares its mask.
Result<EvalRow> evaluate(plugin::TechniqueSession& session, const TechniqueSpec& spec, const EvalOptions& o,
                         const metrics::MaskImage& reference, const metrics::CoverageMask& coverage,
                         metrics::MaskImage& mask_out) {
  if (Status s = select_technique(session, spec, o.sets); !s) return s.error();
  if (spec.name == "reference") {  // a reference evaluated as a technique runs to completion first
    const auto t0 = std::chrono::steady_clock::now();
    for (int f = 0; f < 1 + 65536; ++f) {
      if (Status s = session.render(); !s) return s.error();
      if (reference::reference_progress().complete()) break;
    }
    std::fprintf(stderr, "technique reference (%s) done in %.2f s\n", session.params().get_enum("method").c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  if (Status s = render_timed_frames(session, kWarmupFrames, o.frames); !s) return s.error();
  gl::Texture* mask = session.executor().resource(plugin::kShadowMask);
  if (!mask) return make_error("technique '" + spec.label + "' wrote no shadow_mask", ErrorKind::internal);
  mask_out = read_mask_image(*mask);
  auto errors = metrics::compare_masks(mask_out, reference, coverage);
  if (!errors) return errors.error();
  EvalRow row{spec.label, *errors, 0.0};
  // The technique's own passes: everything but the frame's G-buffer prologue and lighting epilogue.
  for (const PassMedian& p : pass_medians(session, o.frames))
    if (p.name != "gbuffer" && p.name != "lighting") row.gpu_ms += p.ms;
  return row;
}

Status write_outputs(const EvalOptions& o, const EvalReport& report, const std::vector<metrics::MaskImage>& masks,
                     const metrics::MaskImage& reference, const metrics::CoverageMask& coverage) {
  if (!o.heatmaps.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.heatmaps, ec);
    if (ec) {
      Error e = make_error("cannot create the heat-map directory: " + ec.message());
      e.file = o.heatmaps;
      return e;
    }
    for (size_t i = 0; i < masks.size(); ++i) {
      auto map = metrics::error_heat_map(masks[i], reference, coverage, kHeatMapScale);
      if (!map) return map.error();
      const std::string path = o.heatmaps + "/" + report.scene + "_" + report.rows[i].technique + "_error.png";
      if (Status s = metrics::write_png(path, *map); !s) return s;
      std::printf("wrote %s\n", path.c_str());
    }
  }
  if (!o.json.empty()) {
    if (Status s = write_file_whole(o.json, eval_report_json(report)); !s) return s;
    std::printf("wrote %s\n", o.json.c_str());
  }
  return {};
}

int cmd_eval(const std::vector<std::string>& argv) {
  if (help_requested(argv))
    return print_help("penumbra eval --scene NAME|FILE --techniques a,b,c [--reference raytraced|raster] "
                                    "[--size WxH] [--shadow-size N] [--rays M] [--samples N] [--json OUT.json] "
                                    "[--heatmaps DIR] [--set k=v]...\n"
                                    "                     [--camera C] [--light-dir X,Y,Z] [--light-size S] [--ground on|off]",
                                    "Renders a ground-truth reference once, then each technique on the same frame,\n"
                                    "and compares shadow masks over receiver pixels (RMSE, RMSE in the penumbra\n"
                                    "0.02 < ref < 0.98, MAE, max error, SSIM, edge error = mean |error| within 3 px\n"
                                    "of a reference edge) and times the technique's passes (median ms).\n"
                                    "Exact hard reference: --light-size 0 (one ray per pixel sample); add\n"
                                    "--set pixel_samples=4 for the pixel-box-filtered (anti-aliased) one.\n"
                                    "See docs/evaluation.md.",
                                    kSpecs);
  auto args = parse_args(argv, kSpecs);
  if (!args) return fail(args.error());
  plugin::TechniqueRegistry registry;
  register_builtin_techniques(registry);
  auto options = parse_eval_options(*args, registry);
  if (!options) return fail(options.error());
  const EvalOptions& o = *options;
  auto scene = load_scene_option(o.scene_name, *args, o.width, o.height);
  if (!scene) return fail(scene.error());

  int code = 0;
  auto ctx = open_context(*args, "eval", &code, 16, 16);
  if (!ctx) return code;
  exec::PassLibrary library = make_pass_library(registry);
  plugin::TechniqueSession session(registry, library);
  session.set_scene(*scene);
  session.compile_options().keep_alive.push_back("gbuffer_position");  // coverage
  if (Status s = session.resize(o.width, o.height); !s) return fail(s.error());
  if (Status s = session.set_shadow_size(o.shadow); !s) return fail(s.error());

  std::fprintf(stderr, "reference (%s) on %s at %dx%d...\n", o.reference.c_str(), scene->name.c_str(), o.width, o.height);
  const auto t0 = std::chrono::steady_clock::now();
  if (Status s = render_reference(session, o); !s) return fail(s.error());
  std::fprintf(stderr, "reference (%s) done in %.2f s\n", o.reference.c_str(),
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  gl::Texture* ref_mask = session.executor().resource(plugin::kShadowMask);
  gl::Texture* position = session.executor().resource("gbuffer_position");
  if (!ref_mask || !position) return fail(make_error("the reference frame lacks shadow_mask or gbuffer_position", ErrorKind::internal));
  const metrics::MaskImage reference = read_mask_image(*ref_mask);
  const metrics::CoverageMask coverage = read_coverage(*position);

  EvalReport report{scene->name, o.reference, {}};
  std::vector<metrics::MaskImage> masks;
  for (const TechniqueSpec& t : o.techniques) {
    std::fprintf(stderr, "technique %s...\n", t.label.c_str());
    metrics::MaskImage mask;
    auto row = evaluate(session, t, o, reference, coverage, mask);
    if (!row) return fail(row.error());
    report.rows.push_back(*row);
    masks.push_back(std::move(mask));
  }
  std::printf("scene %s, reference %s, %dx%d, %zu receiver pixels (%zu in the reference's penumbra)\n",
              report.scene.c_str(), o.reference.c_str(), o.width, o.height,
              report.rows.empty() ? size_t{0} : report.rows[0].errors.pixels,
              report.rows.empty() ? size_t{0} : report.rows[0].errors.penumbra_pixels);
  std::printf("%s", eval_report_table(report).c_str());
  std::printf("ms: median of %d frames of the technique's passes, timed with %s\n", o.frames,
              timing_mode_note(session).c_str());
  if (Status s = write_outputs(o, report, masks, reference, coverage); !s) return fail(s.error());
  return 0;
}

const CommandRegistration reg{"eval", "compare techniques' shadow masks with a ground-truth reference", cmd_eval};

}  // namespace
}  // namespace penumbra::cli
